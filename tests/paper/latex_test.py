"""paper/tools/latex.py: text escaped for LaTeX, and the not-yet-run mark."""
import unittest

import tools_path  # noqa: F401
from latex import escape, macro_definition, not_yet_run


class LatexTest(unittest.TestCase):
    def test_escape(self):
        self.assertEqual(escape("a_b & 5% {x} #1 ~^\\"),
                         r"a\_b \& 5\% \{x\} \#1 \textasciitilde{}\textasciicircum{}\textbackslash{}")

    def test_marks(self):
        self.assertEqual(not_yet_run("dem_pile"), r"\notyetrun{dem\_pile}")
        self.assertEqual(macro_definition("X", "1"), "\\newcommand{\\X}{1}\n")


if __name__ == "__main__":
    unittest.main()
