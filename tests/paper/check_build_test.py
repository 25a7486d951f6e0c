"""paper/tools/check_build.py: unresolved \\input and \\includegraphics are found; page 1 renders."""
import os
import shutil
import subprocess
import tempfile
import unittest

import tools_path  # noqa: F401
from check_build import check, renders_page_one, unresolved
from fake_repository import write


class CheckBuildTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.folder = self.scratch.name
        write(self.folder, "paper.tex", "\\input{sections/a}\n% \\input{sections/commented}\n")
        write(self.folder, "sections/a.tex", "\\includegraphics[width=1cm]{generated/figures/f}\n"
                                             "\\input{generated/macros.tex}\n")
        write(self.folder, "generated/macros.tex", "\n")
        write(self.folder, "generated/figures/f.pdf", "%PDF\n")

    def tearDown(self):
        self.scratch.cleanup()

    def test_everything_resolves(self):
        self.assertEqual(unresolved(self.folder), [])

    def test_a_missing_figure_and_input_are_named(self):
        os.remove(os.path.join(self.folder, "generated/figures/f.pdf"))
        os.remove(os.path.join(self.folder, "generated/macros.tex"))
        self.assertEqual(sorted(unresolved(self.folder)),
                         ["sections/a.tex: \\includegraphics{generated/figures/f} does not resolve",
                          "sections/a.tex: \\input{generated/macros.tex} does not resolve"])

    def test_no_pdf_is_a_problem(self):
        self.assertEqual(check(self.folder, os.path.join(self.folder, "paper.pdf")),
                         [f"{self.folder}/paper.pdf: no PDF"])

    @unittest.skipUnless(shutil.which("pdftoppm") and shutil.which("pdflatex"), "needs poppler-utils and texlive")
    def test_page_one_of_a_real_pdf_renders_and_a_broken_one_does_not(self):
        write(self.folder, "one.tex", "\\documentclass{article}\\begin{document}x\\end{document}\n")
        subprocess.run(["pdflatex", "-interaction=batchmode", "one.tex"], cwd=self.folder, capture_output=True)
        self.assertTrue(renders_page_one(os.path.join(self.folder, "one.pdf")))
        self.assertFalse(renders_page_one(os.path.join(self.folder, "generated/figures/f.pdf")))


if __name__ == "__main__":
    unittest.main()
