"""What the tests that run real programs share (check_readers.py, from_programs.py,
check_decks.py): failing, skipping when a program is missing, running a program, reading our CSV."""

import os
import subprocess
import sys

SKIP = 77


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def missing(what):
    """Skip (exit 77), or fail where FRONTPACK_REQUIRE_READERS=1 (CI: tools/dev.sh test)."""
    if os.environ.get("FRONTPACK_REQUIRE_READERS") == "1":
        fail(what + " is not installed, and FRONTPACK_REQUIRE_READERS=1 (tools/dev.sh test installs it)")
    print("SKIP: " + what + " is not installed (set FRONTPACK_REQUIRE_READERS=1 to make this a failure)")
    sys.exit(SKIP)


def run(command, cwd, expect=0):
    """Runs `command` in `cwd`; fails unless it exits with `expect`. Returns stdout and stderr."""
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if result.returncode != expect:
        fail("%s exited with %d, expected %d:\n%s" % (" ".join(command), result.returncode, expect,
                                                      result.stdout[-4000:]))
    return result.stdout


def read_csv(path, header="x,y,r", at_least=0):
    """A CSV that frontpack wrote: (x, y, r) per disk, or (x, y, r, type) with header x,y,r,type.
    Fails on another header, or with fewer than `at_least` disks (the test wants a real packing)."""
    with open(path, encoding="ascii") as f:
        lines = f.read().splitlines()
    if not lines or lines[0] != header:
        fail("%s: header %r, expected %s" % (path, lines[0] if lines else "", header))
    disks = []
    for line in lines[1:]:
        fields = line.split(",")
        disk = tuple(float(v) for v in fields[:3])
        disks.append(disk + (int(fields[3]),) if len(fields) == 4 else disk)
    if len(disks) < at_least:
        fail("%s: only %d disks; the test wants a real packing" % (path, len(disks)))
    return disks
