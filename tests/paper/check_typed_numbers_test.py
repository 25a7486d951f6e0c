"""paper/tools/check_typed_numbers.py: a typed result fails, stated settings and structure pass."""
import os
import subprocess
import sys
import tempfile
import unittest

import tools_path
from check_typed_numbers import check_file, typed_numbers_in_line

SCRIPT = os.path.join(tools_path.TOOLS, "check_typed_numbers.py")


class TypedNumbersTest(unittest.TestCase):
    def test_a_typed_result_is_found(self):
        self.assertEqual(typed_numbers_in_line("The RMSE falls to 2.61~mm."), ["2.61"])

    def test_a_generated_macro_passes(self):
        self.assertEqual(typed_numbers_in_line(r"The RMSE falls to \GroundFitRmseMm{}~mm."), [])

    def test_stated_settings_pass(self):
        self.assertEqual(typed_numbers_in_line(r"unstable above $\sigma = \stated{1/4}$ (\stated{2005})"), [])

    def test_structure_passes(self):
        for line in (r"\documentclass[11pt,a4paper]{article}", r"\usepackage[margin=2.5cm]{geometry}",
                     r"\includegraphics[width=0.7\textwidth]{generated/figures/fig2}", r"\label{tab:t1}",
                     r"see Table~\ref{tab:t1}", r"\input{generated/tables/table1}", r"\begin{tabular}{l2r}",
                     r"\newcommand{\x}[1]{\textbf{\texttt{#1}}}", r"\vspace{3pt}"):
            self.assertEqual(typed_numbers_in_line(line), [], line)

    def test_a_comment_passes(self):
        self.assertEqual(typed_numbers_in_line(r"text % measured 42 mm once"), [])

    def test_an_escaped_percent_is_not_a_comment(self):
        self.assertEqual(typed_numbers_in_line(r"a gain of 12\% in speed"), ["12"])

    def test_the_bibliography_passes_and_text_after_it_does_not(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "paper.tex")
            with open(path, "w") as f:
                f.write("\\begin{thebibliography}{9}\n\\bibitem{a} J. Fluid Mech. 508 (2004)\n"
                        "\\end{thebibliography}\nafter it 7 grains\n")
            problems = check_file(path)
        self.assertEqual([(p[1], p[2]) for p in problems], [(4, "7")])

    def test_the_command_fails_on_a_planted_number_and_skips_generated_files(self):
        with tempfile.TemporaryDirectory() as folder:
            os.makedirs(os.path.join(folder, "sections"))
            os.makedirs(os.path.join(folder, "generated"))
            with open(os.path.join(folder, "generated", "macros.tex"), "w") as f:
                f.write("\\newcommand{\\X}{3.14}\n")
            with open(os.path.join(folder, "sections", "ground.tex"), "w") as f:
                f.write("The fit gives $\\alpha = \\X$.\n")
            clean = subprocess.run([sys.executable, SCRIPT, folder], capture_output=True, text=True)
            self.assertEqual(clean.returncode, 0, clean.stdout)
            with open(os.path.join(folder, "sections", "ground.tex"), "a") as f:
                f.write("The held-out RMSE is 3.87~mm.\n")
            planted = subprocess.run([sys.executable, SCRIPT, folder], capture_output=True, text=True)
        self.assertEqual(planted.returncode, 1)
        self.assertIn("ground.tex:2: typed number '3.87'", planted.stdout)

    def test_the_paper_sources_have_no_typed_number(self):
        problems = [p for p in check_file_tree(os.path.join(tools_path.REPOSITORY, "paper"))]
        self.assertEqual(problems, [])


def check_file_tree(folder):
    from check_typed_numbers import tex_files
    for path in tex_files([folder]):
        if os.sep + "out" + os.sep not in path:
            yield from check_file(path)


if __name__ == "__main__":
    unittest.main()
