#!/usr/bin/python3
"""Plot line samples of the flow studies (e.g. the cavity centre lines
centerline-u.csv and centerline-v.csv) with their reference points
(<name>-reference.csv, written by the study when a reference is given).

Usage (Debian's interpreter, which has matplotlib):
  /usr/bin/python3 tools/plot-line-samples.py OUT.png DIR/centerline-u.csv [DIR2/...]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(name):
    with open(name) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, files = sys.argv[1], sys.argv[2:]
    fig, axes = plt.subplots(1, len(files), figsize=(5 * len(files), 4.5))
    if len(files) == 1:
        axes = [axes]
    for ax, name in zip(axes, files):
        header, rows = read(name)
        ax.plot([r[0] for r in rows], [r[1] for r in rows], "-",
                label=os.path.dirname(name) or name)
        reference = name[:-4] + "-reference.csv"
        if os.path.exists(reference):
            _, ref = read(reference)
            ax.plot([r[0] for r in ref], [r[1] for r in ref], "o",
                    fillstyle="none", label="reference")
        ax.set_xlabel(header[0])
        ax.set_ylabel(header[1])
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_title(os.path.basename(name))
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
