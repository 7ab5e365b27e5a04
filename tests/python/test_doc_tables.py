"""scripts/doc_tables.py: the generated tables in README.md and docs/ are well formed, the quick ones
match what the code gives now, and the checker fails on a page that was tampered with.

Needs the chaser program (CHASER_CLI, set by CTest); by hand:
CHASER_CLI=build/cli/chaser /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python/test_doc_tables.py
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "scripts" / "doc_tables.py"
QUICK_BLOCK = "gnc-comrade-sync-run"      # one chaser run, well under a second


def doc_tables(cli, *args):
    env = dict(os.environ, CHASER_CLI=str(cli))
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True, text=True, env=env)


@pytest.fixture
def pages_copy(tmp_path):
    """README.md and docs/*.md copied under tmp_path, to tamper with."""
    shutil.copy(REPO / "README.md", tmp_path / "README.md")
    shutil.copytree(REPO / "docs", tmp_path / "docs", ignore=shutil.ignore_patterns("*.png"))
    return tmp_path


def edit(path, old, new, count=1):
    text = path.read_text()
    assert old in text, f"{path}: no '{old}'"
    path.write_text(text.replace(old, new, count))


def block_lines(page, block_id):
    text = page.read_text()
    begin = text.index(f"scripts/doc_tables.py: {block_id} ")
    return text[begin:text.index(f"<!-- end generated: {block_id} -->")]


def test_every_block_is_registered_and_well_formed(cli):
    done = doc_tables(cli, "--check-format")
    assert done.returncode == 0, done.stderr


def test_quick_blocks_are_what_the_code_gives_now(cli):
    done = doc_tables(cli, "--check-quick")
    assert done.returncode == 0, done.stderr


def test_a_changed_number_in_a_quick_block_fails_with_a_diff(cli, pages_copy):
    gnc = pages_copy / "docs" / "gnc.md"
    row = re.search(r"^\| propellant \| ([\d.]+) kg \|", block_lines(gnc, QUICK_BLOCK), re.M)
    edit(gnc, row.group(0), row.group(0).replace(row.group(1), "9" + row.group(1)))
    assert doc_tables(cli, "--check-format", "--root", pages_copy).returncode == 0  # still well formed
    done = doc_tables(cli, "--check-quick", "--ids", QUICK_BLOCK, "--root", pages_copy)
    assert done.returncode == 1
    assert f"block {QUICK_BLOCK} is stale" in done.stderr
    assert f"-| propellant | 9{row.group(1)} kg |" in done.stderr


@pytest.mark.parametrize("old, new, message", [
    (f"<!-- end generated: {QUICK_BLOCK} -->", f"<!-- end generated {QUICK_BLOCK} -->", "malformed marker"),
    (f"<!-- end generated: {QUICK_BLOCK} -->", "", f"block {QUICK_BLOCK} has no end marker"),
    (QUICK_BLOCK, "no-such-table", "block no-such-table is not registered"),
    ("| final speed error |", "| final speed error | 1 |", "cells, the header"),
    ("| final speed error |", "| final velocity error |", "is labelled"),
    ("| < 0.01 m/s |", "| about one cm/s |", "is not numeric"),
])
def test_a_malformed_block_fails_the_format_check(cli, pages_copy, old, new, message):
    edit(pages_copy / "docs" / "gnc.md", old, new, count=-1)
    done = doc_tables(cli, "--check-format", "--root", pages_copy)
    assert done.returncode == 1
    assert message in done.stderr


def test_zhou_2018_figures_are_the_codes_copy():
    """The paper's figures docs/invsim.md's tables print (constants in the script) are those of
    invsim/zhou2018_tables.cpp, the copy chaser fmea compares against."""
    sys.path.insert(0, str(SCRIPT.parent))
    try:
        import doc_tables
    finally:
        sys.path.remove(str(SCRIPT.parent))
    text = (REPO / "invsim" / "zhou2018_tables.cpp").read_text()
    row = re.compile(r'\{"([^"]+)", (true|false), \{([^}]*)\}, ([0-9.]+)\}')
    table4_text = text[text.index("kTable4"):text.index("kTable5")]
    table4 = {m[1]: tuple(int(v) for v in m[3].split(",")) for m in row.finditer(table4_text)}
    assert table4 == doc_tables.ZHOU_TABLE4 and list(table4) == list(doc_tables.ZHOU_TABLE4)
    printed = {m[1]: (float(m[4]) if m[2] == "true" else None) for m in row.finditer(text)}
    assert printed["nominal"] == doc_tables.ZHOU_NOMINAL_KP
    assert {m: printed[m] for m in doc_tables.ZHOU_TABLE5_KP} == doc_tables.ZHOU_TABLE5_KP
