#!/usr/bin/env python3
"""Runs a command with its standard error on a pseudo-terminal, as on an
engineer's terminal (tetsmooth draws its progress line only there), and
prints what the command wrote there, each carriage return shown as a line
break so that every redraw of the line can be read in a log.

Usage: run_on_pty.py COMMAND [ARG...]; exits with the command's status."""
import os
import pty
import subprocess
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    master, slave = pty.openpty()
    proc = subprocess.Popen(sys.argv[1:], stdin=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    written = bytearray()
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO once the command has closed the terminal
            break
        if not chunk:
            break
        written += chunk
    os.close(master)
    status = proc.wait()
    text = written.decode(errors="replace").replace("\r\n", "\n").replace("\r", "\n")
    sys.stdout.write(text)
    sys.exit(status)


if __name__ == "__main__":
    main()
