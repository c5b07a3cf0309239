#!/usr/bin/env python3
"""On a terminal, `hypergas run` says what it sets up before the first collision, then
draws its progress bar; both lines are cleared at the end. Runs the command with stderr on
a pseudo-terminal (the bar and the setup line are drawn only on a terminal) and checks the
bytes it wrote there. Usage: progress_tty.py HYPERGAS_BINARY"""
import os
import pty
import subprocess
import sys
import tempfile


def stderr_on_tty(args, cwd):
    master, slave = pty.openpty()
    p = subprocess.Popen(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(), out.decode(errors="replace")


def main():
    binary = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        cases = [
            (["run", "--engine", "edmd", "--dim", "3", "--n", "4000", "--packing", "0.3",
              "--until", "2", "--out", "e"], "edmd: setting up 4000 particles at packing 0.3"),
            (["run", "--dim", "3", "--n", "20000", "--until", "2", "--out", "d"],
             "dsmc: setting up 20000 particles (delta velocities)"),
        ]
        for args, line in cases:
            code, err = stderr_on_tty([binary] + args, tmp)
            if code != 0:
                failures.append(f"{' '.join(args)}: exit {code}: {err!r}")
                continue
            for want in (line, "% ", "\r\033[K"):
                if want not in err:
                    failures.append(f"{' '.join(args)}: no {want!r} on the terminal: {err!r}")
            if err.find(line) > err.find("%"):
                failures.append(f"{' '.join(args)}: the setup line comes after the bar")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
