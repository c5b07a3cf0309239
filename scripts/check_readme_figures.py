#!/usr/bin/env python3
"""Checks that what the README quotes of the program's output is what the program prints.

- A fenced block right after `<!-- output: CMD -->` is compared with the standard output of
  CMD, run in a scratch folder in which `build` points to the build folder: every line of
  the block that starts with a digit (a table row) must equal a line of the output in every
  whitespace-separated field but the last (the collision rate, which depends on the machine).
- Every row of a README table whose first cell names a CSV file (`name.csv`) and whose
  second cell starts with a backquoted column list (`a,b,c` or `a,b,c,...`) must list the
  first columns of that file's header, in order, as a short run writes them.

Prints one line per difference and exits 1 if there is any.
usage: check_readme_figures.py README.md BUILD_DIR
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

# Short runs that write every file the README's file table describes.
RUNS = [
    ["run", "--engine", "dsmc", "--dim", "3", "--n", "2000", "--until", "2"],
    ["run", "--engine", "edmd", "--dim", "3", "--n", "500", "--packing", "0.3", "--until", "5",
     "--structure"],
]


def output_blocks(lines):
    """(command, block lines) for each block after an `<!-- output: CMD -->` marker."""
    out = []
    for i, line in enumerate(lines):
        m = re.fullmatch(r"<!-- output: (.+) -->", line.strip())
        if not m:
            continue
        if i + 1 >= len(lines) or not lines[i + 1].startswith("```"):
            out.append((m.group(1), None))
            continue
        block = []
        for line2 in lines[i + 2:]:
            if line2.startswith("```"):
                break
            block.append(line2)
        out.append((m.group(1), block))
    return out


def column_lists(lines):
    """(file name, [columns], ends with '...') for each table row describing a CSV file."""
    out = []
    for line in lines:
        m = re.match(r"\|\s*`([\w.]+\.csv)`[^|]*\|\s*`([\w,.]+)`", line)
        if m and "," in m.group(2):
            cols = m.group(2).split(",")
            more = cols[-1] == "..."
            out.append((m.group(1), [c for c in cols if c != "..."], more))
    return out


def main():
    readme, build = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]).resolve()
    lines = readme.read_text().splitlines()
    problems = []
    with tempfile.TemporaryDirectory() as scratch:
        os.symlink(build, os.path.join(scratch, "build"))
        blocks = output_blocks(lines)
        if not blocks:
            problems.append("no <!-- output: CMD --> block")
        for cmd, block in blocks:
            if block is None:
                problems.append(f"`{cmd}`: the marker is not followed by a fenced block")
                continue
            run = subprocess.run(cmd, shell=True, cwd=scratch, capture_output=True, text=True)
            if run.returncode != 0:
                problems.append(f"`{cmd}` failed ({run.returncode}): {run.stderr.strip()}")
                continue
            printed = {tuple(line.split()[:-1]) for line in run.stdout.splitlines()
                       if line.split() and line.split()[0][:1].isdigit()}
            rows = [line for line in block if line.strip()[:1].isdigit()]
            if not rows:
                problems.append(f"`{cmd}`: the README block has no table row")
            for row in rows:
                if tuple(row.split()[:-1]) not in printed:
                    problems.append(f"`{cmd}`: the README's row\n    {row.strip()}\n"
                                    "  is not printed (all fields but the last compared)")
        headers = {}
        hypergas = str(build / "sim" / "hypergas")
        for k, args in enumerate(RUNS):
            folder = os.path.join(scratch, f"run{k}")
            subprocess.run([hypergas, *args, "--out", folder], check=True,
                           capture_output=True)
            for f in pathlib.Path(folder).glob("*.csv"):
                headers.setdefault(f.name, f.read_text().splitlines()[0].split(","))
        lists = column_lists(lines)
        if not lists:
            problems.append("no table row with a CSV file's column list")
        for name, cols, more in lists:
            header = headers.get(name)
            if header is None:
                problems.append(f"{name}: the README lists its columns; no short run wrote it")
            elif header[:len(cols)] != cols or (not more and len(header) != len(cols)):
                problems.append(f"{name}: the README lists `{','.join(cols)}"
                                f"{',...' if more else ''}`, the file has `{','.join(header)}`")
    for p in problems:
        print(f"check_readme_figures: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
