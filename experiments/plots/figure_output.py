"""Where a plot script's figures go: PNG beside the data (the default), or PDF
into the folder REPOSE_PLOT_PDF_DIR names (the paper, paper/tools/figures.py),
so the same script draws both and the paper's figures are the experiments'.
"""
import os


def save(fig, folder, png_name, **savefig_args):
    """Saves `fig` as FOLDER/PNG_NAME, or as REPOSE_PLOT_PDF_DIR/STEM.pdf when that is set."""
    pdf_dir = os.environ.get("REPOSE_PLOT_PDF_DIR")
    if pdf_dir:
        stem = os.path.splitext(png_name)[0]
        savefig_args.pop("dpi", None)
        fig.savefig(os.path.join(pdf_dir, stem + ".pdf"), **savefig_args)
    else:
        fig.savefig(os.path.join(folder, png_name), **savefig_args)
