"""scripts/run_on_pty.py, which the device's cli step uses to show the progress
line: the command's standard error reaches it as a terminal, what it wrote
comes back with each carriage return made a line break, and its exit status
is passed on."""
import os
import subprocess
import sys
import unittest

SCRIPT = os.path.join(os.environ.get("TETSMOOTH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")),
                      "scripts", "run_on_pty.py")

CHILD = ("import os, sys\n"
         "sys.stderr.write('terminal' if os.isatty(2) else 'not a terminal')\n"
         "sys.stderr.write('\\r  sweep 1\\r  sweep 2\\r\\n')\n"
         "sys.stderr.flush()\n"
         "sys.exit(int(sys.argv[1]))\n")


class RunOnPty(unittest.TestCase):
    def run_child(self, status):
        return subprocess.run([sys.executable, SCRIPT, sys.executable, "-c", CHILD, str(status)],
                              capture_output=True, text=True, timeout=60)

    def test_standard_error_is_a_terminal_and_redraws_become_lines(self):
        proc = self.run_child(0)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout, "terminal\n  sweep 1\n  sweep 2\n\n")

    def test_exit_status_is_passed_on(self):
        self.assertEqual(self.run_child(3).returncode, 3)

    def test_usage_without_a_command(self):
        proc = subprocess.run([sys.executable, SCRIPT], capture_output=True, text=True, timeout=60)
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("Usage", proc.stderr)


if __name__ == "__main__":
    unittest.main()
