"""The frontpack tool's files and signals (issue: outputs, signals and extreme inputs never lose or
clobber data), run as a user would run it.

Usage: files_and_signals.py TOOL SHAPES_DIR [unittest options, e.g. -k Signals]

- Outputs go where the user pointed: /dev/stdout, /dev/stderr, /dev/null, a FIFO are written
  through (not replaced), a symlink is followed, /dev/full fails with exit 2 and the system's
  message; device files are made with mknod in the test's own directory when run as root.
- The same file given for two uses, or an input given as an output, is refused before any work
  with exit 1 and a message naming both uses; no file is created or changed.
- SIGINT, SIGTERM and SIGHUP during generation, certification, statistics and writing: exit
  128 + N within a second, no temporary file, every output file as it was before the run.
- A fill that places no disk exits 8 and writes nothing; one stopped at --max-disks exits 9 and
  says so under --quiet.
- A deck's directories (--deck SIMULATOR DIR, DIR and its missing parents) are made for the run
  and removed again when it fails or is interrupted: a run that writes nothing leaves no new
  directory.
"""
import hashlib
import json
import os
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
import unittest

TOOL = None
SHAPES = None
SQUARE = "POLYGON((0 0,1 0,1 1,0 1,0 0))"


def run(*args, **kw):
    return subprocess.run([TOOL, *args], capture_output=True, text=True, timeout=600, **kw)


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


class Scratch:
    def __init__(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="frontpack-tool-")
        self.dir = self.tmp.name

    def path(self, name):
        return os.path.join(self.dir, name)

    def entries(self):
        return sorted(os.listdir(self.dir))

    def temporaries(self):
        return [e for e in os.listdir(self.dir) if e.startswith(".")]

    def cleanup(self):
        self.tmp.cleanup()


class Outputs(unittest.TestCase):
    def setUp(self):
        self.s = Scratch()
        self.shape = os.path.join(SHAPES, "l_shape.wkt")

    def tearDown(self):
        self.s.cleanup()

    def test_stdout_and_stderr_are_written_through(self):
        r = run("fill", self.shape, "-q", "-o", "/dev/stdout", "--format", "csv", "--json", "/dev/stderr")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(r.stdout.startswith("x,y,r\n"), r.stdout[:100])
        self.assertGreater(r.stdout.count("\n"), 100)
        self.assertEqual(json.loads(r.stderr)["command"], "fill")

    def test_stdout_redirected_to_a_file_appends_like_the_shell(self):
        out = self.s.path("out.csv")
        with open(out, "w") as f:
            f.write("before\n")
        inode = os.stat(out).st_ino
        with open(out, "a") as f:
            r = subprocess.run([TOOL, "fill", self.shape, "-q", "-o", "/dev/stdout", "--format", "csv"], stdout=f,
                               stderr=subprocess.PIPE, text=True, timeout=600)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(os.stat(out).st_ino, inode, "the file was replaced, not written through")
        with open(out) as f:
            text = f.read()
        self.assertTrue(text.startswith("before\nx,y,r\n"), text[:60])
        self.assertEqual(self.s.temporaries(), [])

    def test_dev_null_stays_a_device(self):
        r = run("fill", self.shape, "-q", "-o", "/dev/null", "--format", "csv", "--json", "/dev/null")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(stat.S_ISCHR(os.stat("/dev/null").st_mode))

    def test_dev_full_fails_with_the_system_message(self):
        r = run("fill", self.shape, "-q", "-o", "/dev/full", "--format", "csv")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("cannot write '/dev/full': No space left on device", r.stderr)

    def test_device_files_made_here(self):
        if os.geteuid() != 0:
            self.skipTest("mknod needs root")
        null, full = self.s.path("null"), self.s.path("full")
        os.mknod(null, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
        os.mknod(full, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
        r = run("fill", self.shape, "-q", "-o", null, "--format", "csv")
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run("fill", self.shape, "-q", "-o", full, "--format", "lammps")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("No space left on device", r.stderr)
        for p in (null, full):
            self.assertTrue(stat.S_ISCHR(os.lstat(p).st_mode), p)
        self.assertEqual(self.s.entries(), ["full", "null"])

    def test_fifo_is_written_through(self):
        fifo = self.s.path("p.csv")
        os.mkfifo(fifo)
        got = {}

        def reader():
            with open(fifo) as f:
                got["text"] = f.read()

        t = threading.Thread(target=reader)
        t.start()
        r = run("fill", self.shape, "-q", "-o", fifo)
        t.join(60)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(got["text"].startswith("x,y,r\n"))
        self.assertTrue(stat.S_ISFIFO(os.lstat(fifo).st_mode))
        self.assertEqual(self.s.entries(), ["p.csv"])

    def test_symlink_is_followed(self):
        real, link = self.s.path("real.csv"), self.s.path("link.csv")
        with open(real, "w") as f:
            f.write("old\n")
        os.symlink("real.csv", link)
        r = run("fill", self.shape, "-q", "-o", link)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.islink(link))
        with open(real) as f:
            self.assertTrue(f.read().startswith("x,y,r\n"))
        self.assertEqual(self.s.entries(), ["link.csv", "real.csv"])


class Clobbering(unittest.TestCase):
    def setUp(self):
        self.s = Scratch()
        self.shape = self.s.path("in.wkt")
        with open(os.path.join(SHAPES, "l_shape.wkt")) as f, open(self.shape, "w") as g:
            g.write(f.read())
        self.disks = self.s.path("ok.csv")
        r = run("fill", self.shape, "-q", "-o", self.disks)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.before = {e: digest(self.s.path(e)) for e in self.s.entries()}

    def tearDown(self):
        self.s.cleanup()

    def refused(self, args, *uses):
        r = run(*args)
        self.assertEqual(r.returncode, 1, r.stderr)
        for u in uses:
            self.assertIn(u, r.stderr)
        self.assertEqual({e: digest(self.s.path(e)) for e in self.s.entries()}, self.before,
                         "a file was created or changed")
        self.assertIn("frontpack: ", r.stderr)
        self.assertLess(len(r.stderr.splitlines()), 3, r.stderr)

    def test_same_output_twice(self):
        x = self.s.path("x.csv")
        self.refused(["fill", self.shape, "-o", x, "--json", x], "two outputs", "-o", "--json")
        self.refused(["fill", self.shape, "-o", x, "-o", os.path.join(self.s.dir, ".", "x.csv"), "--format", "csv"],
                     "two outputs")

    def test_input_as_output(self):
        self.refused(["fill", self.shape, "-o", self.shape, "--format", "csv"], "the input DOMAIN", "-o")
        self.refused(["check", self.shape, self.disks, "--json", self.disks], "the input DISKS", "--json")
        self.refused(["stats", self.shape, self.disks, "--json", self.disks], "the input DISKS", "--json")
        self.refused(["render", self.shape, self.disks, "-o", self.shape, "--format", "svg"], "the input DOMAIN")
        link = self.s.path("link.csv")
        os.symlink("ok.csv", link)
        self.before["link.csv"] = digest(link)
        self.refused(["check", self.shape, link, "--json", self.disks], "the input DISKS")


class Outcomes(unittest.TestCase):
    def setUp(self):
        self.s = Scratch()

    def tearDown(self):
        self.s.cleanup()

    def test_no_disk_fits(self):
        out = self.s.path("p.csv")
        for args in (["--radius", "constant:2"], ["--radius", "constant:0.6", "--method", "closed"]):
            r = run("fill", "--wkt", SQUARE, *args, "-q", "-o", out)
            self.assertEqual(r.returncode, 8, r.stderr)
            self.assertIn("no disk fits", r.stderr)
            self.assertEqual(self.s.entries(), [])
        # A corridor narrower than the smallest disk.
        r = run("fill", "--wkt", "POLYGON((0 0,10 0,10 0.1,0 0.1,0 0))", "--radius", "uniform:0.06,0.08", "-o", out)
        self.assertEqual(r.returncode, 8, r.stderr)
        self.assertEqual(self.s.entries(), [])

    def test_stopped_at_max_disks_says_so_under_quiet(self):
        # The closed form overhangs a box smaller than a few disks: it generates more disks than
        # the estimate (7 here), so --max-disks 7 passes the up-front check and stops the run.
        out = self.s.path("p.csv")
        r = run("fill", "--wkt", SQUARE, "--radius", "constant:0.2", "--method", "closed", "--max-disks", "7",
                "-q", "-o", out)
        self.assertEqual(r.returncode, 9, r.stderr)
        self.assertIn("stopped at --max-disks 7", r.stderr)
        self.assertEqual(self.s.entries(), ["p.csv"])
        check = run("check", os.path.join(SHAPES, "unit_square.wkt"), out)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)

    def test_default_radius_is_named(self):
        j = self.s.path("s.json")
        r = run("fill", "--wkt", SQUARE, "--json", j)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("uniform:0.01,0.05 (the default", r.stderr)
        with open(j) as f:
            summary = json.load(f)
        self.assertEqual(summary["radius_spec"], "uniform:0.01,0.05")
        self.assertFalse(summary["radius_spec_given"])


class DeckDirectories(unittest.TestCase):
    """--deck yade fresh/a/b: the directories a run makes are gone again unless it commits."""

    def setUp(self):
        self.s = Scratch()
        os.mkdir(self.s.path("old"))

    def tearDown(self):
        self.s.cleanup()

    def deck_args(self, radius):
        return ["fill", "--wkt", SQUARE, "--radius", radius, "-q", "--density", "2500", "--deck", "yade"]

    def test_failed_run_leaves_no_new_directory(self):
        for deck in ("fresh/a/b", "old/new/c"):
            r = run(*self.deck_args("constant:2"), self.s.path(deck))
            self.assertEqual(r.returncode, 8, r.stderr)
            self.assertEqual(self.s.entries(), ["old"], deck)
            self.assertEqual(os.listdir(self.s.path("old")), [], deck)

    def test_interrupted_run_leaves_no_new_directory(self):
        for sig, deck in ((signal.SIGINT, "fresh/a/b"), (signal.SIGTERM, "old/new/c")):
            p = subprocess.Popen([TOOL, *self.deck_args("uniform:0.0005,0.001"), self.s.path(deck)],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            time.sleep(0.3)  # generation of about 540,000 disks: about a second
            self.assertIsNone(p.poll(), "the run ended before its signal")
            p.send_signal(sig)
            code = wait_exit(p, 10)
            _, err = p.communicate()
            self.assertEqual(code, 128 + sig, err)
            self.assertEqual(self.s.entries(), ["old"], deck)
            self.assertEqual(os.listdir(self.s.path("old")), [], deck)

    def test_blocked_run_leaves_no_new_directory(self):
        # Blocked on a FIFO without reader the run cannot unwind: the signal watcher's last resort
        # removes the new directories with the temporary files.
        fifo = self.s.path("old/p.csv")
        os.mkfifo(fifo)
        p = subprocess.Popen([TOOL, *self.deck_args("uniform:0.05,0.1"), self.s.path("fresh/a/b"), "-o", fifo],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(1.0)  # the fill is done; the tool waits for the FIFO's reader
        self.assertIsNone(p.poll())
        p.send_signal(signal.SIGTERM)
        code = wait_exit(p, 10)
        _, err = p.communicate()
        self.assertEqual(code, 143, err)
        self.assertEqual(self.s.entries(), ["old"])
        self.assertEqual(os.listdir(self.s.path("old")), ["p.csv"])

    def test_complete_run_keeps_its_directories(self):
        r = run(*self.deck_args("uniform:0.05,0.1"), self.s.path("fresh/a/b"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("run.py", os.listdir(self.s.path("fresh/a/b")))


def wait_exit(p, limit):
    try:
        p.wait(limit)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        return None
    return p.returncode


class Signals(unittest.TestCase):
    """A fill of about 540,000 disks to CSV, LAMMPS, PNG and JSON, signalled in each phase (each
    phase lasts 0.1-0.6 s in Release, several times that under ASan: long enough to be hit at its
    middle; the test runs alone, and its share of CI is what sets the size).

    The phases' times come from a calibration run's JSON summary (seconds of generation,
    certification and statistics) and its wall time (the rest is loading and writing)."""

    RADIUS = "uniform:0.0005,0.001"
    calibration = None

    def args(self, d):
        return ["fill", "--wkt", SQUARE, "--radius", self.RADIUS, "-q", "-o", os.path.join(d, "p.csv"),
                "-o", os.path.join(d, "p.data"), "-o", os.path.join(d, "p.png"), "--width", "1200",
                "--json", os.path.join(d, "s.json")]

    @classmethod
    def calibrate(cls):
        if cls.calibration is None:
            s = Scratch()
            t0 = time.monotonic()
            r = run(*cls.args(cls, s.dir))
            wall = time.monotonic() - t0
            assert r.returncode == 0, r.stderr
            with open(s.path("s.json")) as f:
                sec = json.load(f)["seconds"]
            s.cleanup()
            startup = 0.05
            front = startup + sec["front"]
            certify = front + sec["cull"] + sec["overlap_pass"]
            stats = certify + sec["statistics"]
            cls.calibration = {
                "generation": startup + 0.5 * sec["front"],
                "certification": front + 0.5 * (sec["cull"] + sec["overlap_pass"]),
                "statistics": certify + 0.5 * sec["statistics"],
                "writing": stats + 0.5 * max(0.0, wall - stats),
            }
        return cls.calibration

    def signalled(self, sig, phase, attempts=3):
        """Signals a run in `phase`; a run that ended before its signal (the machine was faster
        than in the calibration) is tried again with the signal sent earlier."""
        for attempt in range(attempts):
            took = self.signal_once(sig, phase, 0.6 ** attempt)
            if took is not None:
                return took
        self.fail(f"every run ended before its signal ({phase})")

    def signal_once(self, sig, phase, scale):
        at = self.calibrate()[phase] * scale
        s = Scratch()
        try:
            old = {}
            for name in ("p.csv", "p.data", "s.json"):
                with open(s.path(name), "w") as f:
                    f.write("old " + name + "\n")
                old[name] = digest(s.path(name))
            p = subprocess.Popen([TOOL, *self.args(s.dir)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            time.sleep(at)
            if p.poll() is not None:
                p.communicate()
                return None
            t0 = time.monotonic()
            p.send_signal(sig)
            code = wait_exit(p, 10)
            took = time.monotonic() - t0
            _, err = p.communicate()
            print(f"  {signal.Signals(sig).name} in {phase} at {at:.2f} s: exit {code} {took:.3f} s later",
                  file=sys.stderr)
            if code == 0:
                # The signal came after the outputs were committed (the run was that close to its
                # end): the run is complete, every output new, and it counts as ended before its
                # signal. A tool that ignored signals while writing fails every attempt here.
                self.assertEqual(s.temporaries(), [], f"{phase}: temporary files left")
                for name, h in old.items():
                    self.assertNotEqual(digest(s.path(name)), h, f"{phase}: exit 0 but {name} not written")
                return None
            self.assertEqual(code, 128 + sig, f"{phase}: {err}")
            self.assertLess(took, 1.0, f"{phase}: exit {took:.2f} s after the signal")
            self.assertIn("interrupted by " + signal.Signals(sig).name, err)
            self.assertEqual(s.temporaries(), [], f"{phase}: temporary files left")
            self.assertEqual(sorted(s.entries()), sorted(old), f"{phase}: a new output appeared")
            for name, h in old.items():
                self.assertEqual(digest(s.path(name)), h, f"{phase}: {name} was changed")
            return took
        finally:
            s.cleanup()

    def test_sigint_in_every_phase(self):
        for phase in ("generation", "certification", "statistics", "writing"):
            self.signalled(signal.SIGINT, phase)

    def test_sigterm_in_every_phase(self):
        for phase in ("generation", "certification", "statistics", "writing"):
            self.signalled(signal.SIGTERM, phase)

    def test_sighup(self):
        self.signalled(signal.SIGHUP, "generation")

    def test_blocked_on_a_fifo_without_reader(self):
        s = Scratch()
        try:
            fifo = s.path("p.csv")
            os.mkfifo(fifo)
            p = subprocess.Popen([TOOL, "fill", "--wkt", SQUARE, "-q", "-o", s.path("q.csv"), "-o", fifo],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            time.sleep(1.0)  # the fill is done; the tool waits for the FIFO's reader
            self.assertIsNone(p.poll())
            t0 = time.monotonic()
            p.send_signal(signal.SIGTERM)
            code = wait_exit(p, 10)
            _, err = p.communicate()
            self.assertEqual(code, 143, err)
            self.assertLess(time.monotonic() - t0, 1.0)
            self.assertEqual(s.entries(), ["p.csv"])
        finally:
            s.cleanup()


if __name__ == "__main__":
    TOOL, SHAPES = sys.argv[1], sys.argv[2]
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]], verbosity=2)
