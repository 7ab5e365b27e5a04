"""chaser.view: the page of a chaser.run(out=...) folder, as `chaser view` writes it."""
import json

import pytest

import chaser
from conftest import MSR, run_cli


def test_a_run_written_from_python_replays_as_the_command_line_writes_it(cli, tmp_path):
    py_out, cli_out = tmp_path / "py", tmp_path / "cli"
    chaser.run(chaser.load_scenario(str(MSR), overrides=["duration_s=30"]), out=str(py_out))
    shown = run_cli(cli, "run", MSR, "--out", cli_out, "--set", "duration_s=30")
    assert shown.returncode == 0, shown.stderr
    assert (py_out / "geometry.json").read_bytes() == (cli_out / "geometry.json").read_bytes()
    geometry = json.loads((py_out / "geometry.json").read_text())
    assert [t["name"] for t in geometry["chaser"]["thrusters"]] == [f"T{i}" for i in range(1, 17)]

    written = chaser.view(str(py_out))
    assert written == str(py_out / "view.html")
    page = (py_out / "view.html").read_text()
    assert '<script type="application/json" id="chaser-data">' in page
    shown = run_cli(cli, "view", cli_out, "--out", tmp_path / "cli.html")
    assert shown.returncode == 0, shown.stderr
    assert (tmp_path / "cli.html").read_text() == page  # the page holds no path of its folder


def test_a_folder_without_its_summary_is_refused_by_name(tmp_path):
    chaser.run(chaser.load_scenario(str(MSR), overrides=["duration_s=5"]), out=str(tmp_path))
    (tmp_path / "summary.json").unlink()
    with pytest.raises(ValueError, match="summary.json: missing"):
        chaser.view(str(tmp_path), out=str(tmp_path / "page.html"))
    assert not (tmp_path / "page.html").exists()
