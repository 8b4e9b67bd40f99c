"""import grainlab under an interpreter that cannot load its compiled part (here: the same
python3 with -S, so Debian's dist-packages and numpy are not on the path) must say which
interpreter the module is built for, not fail on a bare "No module named numpy"."""
import os
import subprocess
import sys
import unittest


class InterpreterCheck(unittest.TestCase):
    def run_import(self, *flags):
        return subprocess.run([sys.executable, *flags, "-c", "import grainlab"],
                              capture_output=True, text=True, env=dict(os.environ))

    def test_system_python_imports(self):
        result = self.run_import()
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_python_without_numpy_is_told_which_to_use(self):
        result = self.run_import("-S")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("ImportError", result.stderr)
        self.assertIn("/usr/bin/python3", result.stderr)
        self.assertIn("python3-numpy", result.stderr)
        self.assertIn("_grainlab", result.stderr)


if __name__ == "__main__":
    unittest.main()
