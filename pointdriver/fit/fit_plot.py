#!/usr/bin/env python3
"""Overlay figures of `pointdriver fit` and `pointdriver check` (python3 + matplotlib).

  fit_plot.py SPEC.json

SPEC.json (written by the commands): {"model_label": ..., "reference_label": ...,
"figures": [{"file": PNG, "title": ..., "curves": [{"label": ..., "data": [[eps_p, MPa], ...],
"model": [[eps_p, MPa], ...], "reference": [[eps_p, MPa], ...] (optional)}]}]}.
Data are markers, the model solid lines, the reference (e.g. the published set) dashed lines, one
colour per curve; at most 6 curves per panel (a group with more gets several panels). Exit codes: 0 done, 2 input error, 4 matplotlib missing.
"""

import json
import sys


def main(argv):
    if len(argv) != 1:
        sys.stderr.write(__doc__)
        return 1
    try:
        with open(argv[0]) as f:
            spec = json.load(f)
    except (OSError, ValueError) as e:
        sys.stderr.write(f"fit_plot.py: {argv[0]}: {e}\n")
        return 2
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("fit_plot.py: matplotlib is missing: apt-get install -y python3-matplotlib\n")
        return 4
    model_label = spec.get("model_label", "model")
    reference_label = spec.get("reference_label", "reference")
    per_panel = 6
    for fig_spec in spec["figures"]:
        curves = fig_spec["curves"]
        panels = [curves[i : i + per_panel] for i in range(0, len(curves), per_panel)]
        ncols = 1 if len(panels) == 1 else 2
        nrows = (len(panels) + ncols - 1) // ncols
        fig, axes = plt.subplots(nrows, ncols, figsize=(7.5 * ncols, 4.8 * nrows), squeeze=False)
        colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for p, panel in enumerate(panels):
            ax = axes[p // ncols][p % ncols]
            for i, c in enumerate(panel):
                col = colours[i % len(colours)]
                if c.get("data"):
                    x, y = zip(*c["data"])
                    ax.plot(x, y, "o", color=col, markersize=3.5, label=c["label"])
                if c.get("model"):
                    x, y = zip(*c["model"])
                    ax.plot(x, y, "-", color=col, linewidth=1.4)
                if c.get("reference"):
                    x, y = zip(*c["reference"])
                    ax.plot(x, y, "--", color=col, linewidth=1.0, alpha=0.8)
            ax.plot([], [], "k-", label=model_label)
            if any(c.get("reference") for c in panel):
                ax.plot([], [], "k--", label=reference_label)
            ax.set_xlabel("true plastic strain [-]")
            ax.set_ylabel("true stress [MPa]")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
        for p in range(len(panels), nrows * ncols):
            axes[p // ncols][p % ncols].axis("off")
        fig.suptitle(fig_spec.get("title", ""))
        fig.tight_layout()
        fig.savefig(fig_spec["file"], dpi=100)
        plt.close(fig)
        print(f"wrote {fig_spec['file']}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
