"""MSR branch A geometry (M_F, M_C), mean motion and a quaternion-to-matrix helper, read from the shipped scenario."""
from pathlib import Path
import yaml, numpy as np
sc=yaml.safe_load(open(Path(__file__).resolve().parents[2] / 'scenarios' / 'msr_terminal.yaml'))
A=[t for t in sc['thrusters']['list'] if t['branch']=='A']
P=np.array([t['position_body_m'] for t in A]); D=np.array([t['direction_body'] for t in A],float)
D/=np.linalg.norm(D,axis=1)[:,None]
F=22.0*D; Tq=np.cross(P,F)
MF=F.T; MC=Tq.T   # 3x8
mu=float(sc['orbit']['mu_m3ps2']); R=float(sc['orbit']['body_radius_m'])+float(sc['orbit']['altitude_m']); n=np.sqrt(mu/R**3)
def qmat(q):
    w,x,y,z=q
    return np.array([[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]])
def R_lvlh_from_body(t,row):
    q=[row['q_inertial_from_body_'+c] for c in 'wxyz']
    th=n*t; Rz=np.array([[np.cos(th),-np.sin(th),0],[np.sin(th),np.cos(th),0],[0,0,1]])
    return Rz.T@qmat(q)
