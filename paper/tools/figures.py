"""The paper's figures as PDF (generated/figures/NAME.pdf): each experiment's
own plot script (experiments/plots/*.py) run again on its folder with
REPOSE_PLOT_PDF_DIR set, so it writes PDF there instead of PNG beside the data
(experiments/plots/figure_output.py). An experiment without a folder gets a
placeholder page that says so, so every \\includegraphics still resolves.
"""
import os
import shutil
import subprocess
import tempfile

PYTHON = "/usr/bin/python3"


def run_plot(root, script, folder, pdf_dir):
    env = dict(os.environ, MPLBACKEND="Agg", REPOSE_PLOT_PDF_DIR=pdf_dir)
    result = subprocess.run([PYTHON, os.path.join(root, script), folder], env=env, cwd=root,
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"{script} {folder}: failed (exit status {result.returncode}):\n{result.stderr[-2000:]}")


def placeholder(path, experiment_id):
    """A small PDF that says which experiment has not been run."""
    script = ("import sys, matplotlib\nmatplotlib.use('Agg')\nimport matplotlib.pyplot as plt\n"
              "fig = plt.figure(figsize=(6, 1.6))\n"
              "fig.text(0.5, 0.5, 'not yet run: ' + sys.argv[2] + '\\n(scripts/make-paper.sh --full)',"
              " ha='center', va='center', fontsize=12)\nfig.savefig(sys.argv[1])\n")
    subprocess.run([PYTHON, "-c", script, path, experiment_id], check=True, env=dict(os.environ, MPLBACKEND="Agg"))


def write_figures(root, out_dir, inputs, statuses):
    """Writes every figure of inputs.yaml; runs each (script, folder) pair once."""
    os.makedirs(out_dir, exist_ok=True)
    made = {}
    with tempfile.TemporaryDirectory(prefix="paper-figures-") as scratch:
        for figure in inputs.figures:
            target = os.path.join(out_dir, f"{figure.name}.pdf")
            status = statuses.get(figure.experiment)
            if status is None or not status.usable:
                placeholder(target, figure.experiment)
                continue
            folder = os.path.join(status.folder, figure.subfolder) if figure.subfolder else status.folder
            key = (figure.script, folder)
            if key not in made:
                made[key] = os.path.join(scratch, str(len(made)))
                os.makedirs(made[key])
                run_plot(root, figure.script, folder, made[key])
            written = os.path.join(made[key], figure.output)
            if not os.path.exists(written):
                raise RuntimeError(f"figures.{figure.name}: {figure.script} wrote no {figure.output} "
                                   f"(it wrote: {', '.join(sorted(os.listdir(made[key]))) or 'nothing'})")
            shutil.copyfile(written, target)
