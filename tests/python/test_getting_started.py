"""docs/getting-started.md: every output the page shows is what its commands print now.

The page is read as a script. Its ```sh blocks run in order, with bash, in a fresh folder laid out
like the repository: scenarios/ and python/ linked to the repository's, build/cli/chaser to the
program under test (CHASER_CLI) and build/python to the module's folder. Between them the test makes
the edits to my_approach.yaml that the page's prose asks for (EDITS; each is made just before the
first command after its sentence, and the sentence must still be on the page). Nothing is written
in the repository.

A plain ``` block right after a ```sh block (prose may come between) is what that block prints,
stdout and stderr together. A plain block after another plain block shows a file (FILES). The
```python block is run as a doctest. The match is the page's own rule, "abridged where marked
`...`": a line `...` stands for any number of lines left out, `...` inside a line for any text (the
page writes wall-clock timings that way), and every other shown line must be the next line of the
output, in order, with the block's first and last lines the output's first and last unless a `...`
stands before or after them. Lines are compared with trailing spaces removed; nothing else is
normalised. Not run: `make ...` (the build) and the bare interpreter the ```python block is typed
into.

Measured: the whole file in about 9 s on 2 cores (Release build), nearly all of it the page's own
commands; each tampered copy takes under 0.1 s.
By hand: PYTHONPATH=build/python CHASER_CLI=build/cli/chaser /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python/test_getting_started.py
"""
import contextlib
import difflib
import doctest
import io
import os
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest

import chaser
from conftest import REPO

PAGE = REPO / "docs" / "getting-started.md"
LINKED = ("scenarios", "python")          # the repository's folders the page's commands read
COMMAND_TIMEOUT_S = 60
SKIPPED = (re.compile(r"make\b"),         # builds: not this test's business
           re.compile(r"PYTHONPATH=\S+ /usr/bin/python3$"))  # the interpreter the ```python block runs in


@dataclass(frozen=True)
class Edit:
    """An edit the page's prose asks for: `sentence` (on the page) says it; `pattern` (a regular
    expression, multiline) must match `count` times in `path`; `new` replaces it, or, when None, the
    ```yaml block that follows the sentence replaces it."""
    sentence: str
    path: str
    pattern: str
    new: str | None
    count: int = 1


EDITS = (
    Edit("change `name: msr_terminal` to `name: my_approach`", "my_approach.yaml",
         r"^name: msr_terminal$", "name: my_approach"),
    Edit("`[ 1.0,   0.8,   0.8 ]` to `[ 0.5,   0.8,   0.8 ]`", "my_approach.yaml",
         r"(^    - \{name: T1, .*position_body_m: )\[ 1\.0,   0\.8,   0\.8 \]", r"\1[ 0.5,   0.8,   0.8 ]"),
    Edit("Delete the last line of `thrusters.list` (T16", "my_approach.yaml",
         r"^    - \{name: T16,.*\n(?!    - )", ""),
    Edit("set `enabled: false` in both `position:` and `attitude:`", "my_approach.yaml",
         r"(^  (?:position|attitude):.*\n    enabled: )true$", r"\1false", count=2),
    Edit("Put a leak of T2 in the file, replacing `faults: []`", "my_approach.yaml",
         r"^faults: \[\].*$", None),
)

# Plain blocks that follow no command: the file each shows, in the folder the page works in.
FILES = {"### Scheme: deficit": "out/camp/summary.md"}


@dataclass(frozen=True)
class Block:
    kind: str     # the fence's info string: "sh", "" (output), "python", "yaml"
    text: str
    line: int     # the page's line of its first content line (1-based)
    offset: int   # where its fence starts in the page's text


def parse_blocks(text):
    blocks, kind, start, body, offset = [], None, 0, [], 0
    position = 0
    for number, line in enumerate(text.splitlines(keepends=True), start=1):
        fence = line.rstrip("\n")
        if kind is None and fence.startswith("```"):
            kind, start, body, offset = fence[3:].strip(), number + 1, [], position
        elif kind is not None and fence == "```":
            blocks.append(Block(kind, "".join(body), start, offset))
            kind = None
        elif kind is not None:
            body.append(line)
        position += len(line)
    assert kind is None, f"a block from line {start} is never closed"
    return blocks


def shown_lines(block):
    return [(block.line + i, line.rstrip()) for i, line in enumerate(block.text.splitlines())]


def line_matches(shown, actual):
    if "..." not in shown:
        return shown == actual
    return re.fullmatch(".*".join(re.escape(part) for part in shown.split("...")), actual) is not None


def compare(page_name, block, output, what):
    """Problems of `output` (text) against the shown block, one per mismatch, naming the page's line."""
    actual = [line.rstrip() for line in output.splitlines()]
    lines = shown_lines(block)
    groups, group = [], []                # runs of shown lines between `...` lines
    for number, line in lines:
        if line == "...":
            groups.append(group)
            group = []
        else:
            group.append((number, line))
    groups.append(group)
    anchored_start, anchored_end = groups[0] != [], groups[-1] != []
    cursor = 0
    for index, group in enumerate(groups):
        if not group:
            continue
        last = index == len(groups) - 1 and anchored_end
        starts = [cursor] if index == 0 and anchored_start else range(cursor, len(actual) - len(group) + 1)
        if last:
            starts = [s for s in starts if s == len(actual) - len(group)]
        found = next((s for s in starts if group_at(group, actual, s)), None)
        if found is not None:
            cursor = found + len(group)
            continue
        return [anchor_mismatch(page_name, group, actual, what, cursor, index == 0 and anchored_start, last)
                or mismatch(page_name, group, actual, [cursor] if index == 0 and anchored_start else
                            range(cursor, len(actual)), what, cursor)]
    return []


def group_at(group, actual, start):
    return start + len(group) <= len(actual) and all(line_matches(shown, actual[start + k]) for k, (_, shown) in enumerate(group))


def anchor_mismatch(page_name, group, actual, what, cursor, at_start, at_end):
    """When the shown run is in the output, but not where the block's unmarked first or last line puts it."""
    found = next((s for s in range(cursor, len(actual) - len(group) + 1) if group_at(group, actual, s)), None)
    if found is None:
        return None
    if at_start and found != cursor:
        number, shown = group[0]
        return f"{page_name}:{number}: shown `{shown}` first, but {what} begins with `{actual[0]}`: start the block with `...`"
    if at_end:
        number, shown = group[-1]
        return (f"{page_name}:{number}: shown `{shown}` last, but {what} goes on with `{actual[found + len(group)]}`: "
                f"end the block with `...`")
    return None


def mismatch(page_name, group, actual, starts, what, cursor):
    """The shown run's first line that the output does not have where the run matches longest."""
    best, best_start = -1, None
    for s in starts:
        k = 0
        while k < len(group) and s + k < len(actual) and line_matches(group[k][1], actual[s + k]):
            k += 1
        if k > best:
            best, best_start = k, s
    if best_start is None:                # the output is shorter than the shown run
        number, shown = group[0]
        return f"{page_name}:{number}: shown `{shown}`, but {what} has no such line (after line {cursor} of its {len(actual)})"
    if best == len(group):                # matched, but not where the block's ends put it
        return f"{page_name}:{group[0][0]}: shown `{group[0][1]}`: {what} has it, but not in this place"
    number, shown = group[best]
    there = best_start + best
    if there >= len(actual):
        return f"{page_name}:{number}: shown `{shown}`, but {what} ends before it"
    if best == 0 and len(starts) > 1:     # not even the run's first line: name the output's nearest
        closest = difflib.get_close_matches(shown, actual[cursor:], n=1, cutoff=0.0)
        return f"{page_name}:{number}: shown `{shown}`, but {what} has no such line; the closest: `{closest[0]}`"
    elsewhere = any(line_matches(shown, a) for a in actual)
    hint = " (the shown line is elsewhere in it: mark the lines between with `...`)" if elsewhere else ""
    return f"{page_name}:{number}: shown `{shown}`, but {what} has `{actual[there]}` there{hint}"


def prepare_folder(folder, cli):
    for name in LINKED:
        (folder / name).symlink_to(REPO / name)
    (folder / "build" / "cli").mkdir(parents=True)
    (folder / "build" / "cli" / "chaser").symlink_to(Path(cli).resolve())
    module_dir = Path(chaser.__file__).resolve().parent
    (folder / "build" / "python").symlink_to(module_dir)
    return {**os.environ, "PYTHONPATH": str(module_dir), "PYTHONDONTWRITEBYTECODE": "1"}


def apply_edit(edit, text, blocks, folder):
    new = edit.new
    if new is None:
        yaml = next((b for b in blocks if b.kind == "yaml" and b.offset > text.index(edit.sentence)), None)
        if yaml is None:
            return f"no ```yaml block after '{edit.sentence}'"
        new = yaml.text.rstrip("\n").replace("\\", "\\\\")
    path = folder / edit.path
    content, n = re.subn(edit.pattern, new, path.read_text(), flags=re.M)
    if n != edit.count:
        return f"'{edit.sentence}': {edit.path} has {n} matches of {edit.pattern!r}, the test expects {edit.count}"
    path.write_text(content)
    return None


def run_doctest(page, block, folder):
    test = doctest.DocTestParser().get_doctest(block.text, {}, page.name, str(page), block.line - 1)
    report = io.StringIO()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    with contextlib.chdir(folder):
        runner.run(test, out=report.write, clear_globs=True)
    return [report.getvalue().rstrip()] if runner.failures else []


def check_page(page, cli, folder, edits=EDITS):
    """Runs the page's commands in `folder` and returns its problems: every shown line that is not
    what the code prints, every edit or block the test cannot place. An empty list: the page is right."""
    text = page.read_text()
    blocks = parse_blocks(text)
    env = prepare_folder(folder, cli)
    pending = []
    for edit in edits:
        if edit.sentence not in text:
            return [f"{page.name} no longer says '{edit.sentence}': update the test's EDITS"]
        pending.append(edit)
    problems = []
    for i, block in enumerate(blocks):
        previous = blocks[i - 1].kind if i > 0 else None
        for edit in [e for e in pending if text.index(e.sentence) < block.offset]:
            pending.remove(edit)
            if failed := apply_edit(edit, text, blocks, folder):
                return problems + [f"{page.name}: {failed}"]
        if block.kind == "sh":
            output = blocks[i + 1] if i + 1 < len(blocks) and blocks[i + 1].kind == "" else None
            commands = [c for c in block.text.splitlines() if c.strip()]
            if any(rule.match(c) for c in commands for rule in SKIPPED):
                if output is not None:
                    problems.append(f"{page.name}:{block.line}: a command the test does not run shows an output")
                continue
            done = subprocess.run(["bash", "-c", block.text], cwd=folder, env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True, timeout=COMMAND_TIMEOUT_S)
            if output is not None:
                what = f"the output of `{commands[0]}`" + (f" (exit {done.returncode})" if done.returncode else "")
                problems += compare(page.name, output, done.stdout, what)
        elif block.kind == "" and previous != "sh":
            first = next((line for _, line in shown_lines(block) if line != "..."), "")
            if first not in FILES:
                problems.append(f"{page.name}:{block.line}: a shown output with no command before it and no file "
                                f"in the test's FILES for `{first}`")
                continue
            path = folder / FILES[first]
            content = path.read_text() if path.is_file() else ""
            problems += compare(page.name, block, content, FILES[first])
        elif block.kind == "python":
            problems += run_doctest(page, block, folder)
        elif block.kind not in ("", "yaml"):
            problems.append(f"{page.name}:{block.line}: a ```{block.kind} block: the test does not know it")
    return problems


def test_every_output_the_page_shows_is_what_the_code_prints(cli, tmp_path):
    problems = check_page(PAGE, cli, tmp_path)
    assert not problems, "\n".join(problems)


# Tampered copies of section 3's start (a copy, a validation, an edit and `chaser thrusters`: quick).
def section_3_start():
    text = PAGE.read_text()
    return text[text.index("## 3. "):text.index("**Remove a thruster.**")]


@pytest.mark.parametrize("old, new, culprit, expected", [
    # A changed number.
    ("(scenario 'my_approach', hash ", "(scenario 'my_approach', hash 0", "my_approach.yaml: valid",
     "but the output of `build/cli/chaser validate my_approach.yaml` has `my_approach.yaml: valid"),
    # A line the code does not print.
    ("every direction): yes\n", "every direction): yes\nand a line the code never wrote\n", "and a line the code",
     "shown `and a line the code never wrote`, but the output of `build/cli/chaser thrusters my_approach.yaml` has"),
    # Lines left out without a `...` to say so.
    ("T8\n...\n   Cy [N m]", "T8\n   Cy [N m]", "   Cy [N m]", "mark the lines between with `...`"),
], ids=["changed-number", "unprinted-line", "unmarked-gap"])
def test_a_tampered_page_fails_naming_the_line(cli, tmp_path, old, new, culprit, expected):
    good = section_3_start()
    assert good.count(old) == 1
    page = tmp_path / "getting-started.md"
    page.write_text(good.replace(old, new))
    folder = tmp_path / "work"
    folder.mkdir()
    problems = check_page(page, cli, folder, edits=EDITS[:2])
    assert len(problems) == 1, problems
    text = page.read_text()
    assert text.count(culprit) == 1
    number = text[:text.index(culprit)].count("\n") + 1
    assert problems[0].startswith(f"getting-started.md:{number}: "), problems[0]
    assert expected in problems[0], problems[0]


def test_a_wrong_python_output_fails_naming_the_line(cli, tmp_path):
    page = tmp_path / "getting-started.md"
    page.write_text("Python:\n\n```python\n>>> 6 * 7\n41\n```\n")
    folder = tmp_path / "work"
    folder.mkdir()
    problems = check_page(page, cli, folder, edits=())
    assert len(problems) == 1, problems
    assert f'File "{page}", line 4' in problems[0] and "Expected:\n    41\nGot:\n    42" in problems[0], problems[0]
