"""paper/tools/staleness_report.py: what will run, what is used stale, and why, in words."""
import os
import tempfile
import unittest
from types import SimpleNamespace

import tools_path  # noqa: F401
from staleness_report import report_lines, write_staleness


def status(entry_id, state, reasons=(), command="experiment", optional=False):
    return SimpleNamespace(entry=SimpleNamespace(id=entry_id, command=command, optional=optional),
                           state=state, reasons=list(reasons))


class StalenessReportTest(unittest.TestCase):
    def test_each_state_says_what_happens(self):
        run = status("calibration", "stale", ["code of solver ground: changed"])
        statuses = [run, status("collapse", "missing", ["never run"]),
                    status("pile", "stale", ["scene x: changed"], command="data"),
                    status("scoop", "absent", optional=True), status("table1", "stale", ["input y: changed"])]
        text = "\n".join(report_lines(statuses, [run], "quick"))
        for expected in ("calibration              stale    will run\n      code of solver ground: changed",
                         "not run in quick mode", "remake with scripts/make-canonical-data.sh",
                         "optional, not there", "table1                   stale    used as it is (stale)"):
            self.assertIn(expected, text)

    def test_the_appendix_lists_what_was_not_fresh(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "staleness.tex")
            write_staleness(path, [status("a_b", "stale", ["input c_d: changed"]), status("e", "fresh")])
            with open(path) as f:
                text = f.read()
            self.assertIn("\\item \\texttt{a\\_b} (stale): input c\\_d: changed", text)
            self.assertNotIn("{e}", text)
            write_staleness(path, [status("e", "fresh")])
            with open(path) as f:
                self.assertIn("Every run folder was fresh", f.read())


if __name__ == "__main__":
    unittest.main()
