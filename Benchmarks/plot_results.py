#!/usr/bin/env python3
"""Speed versus error plot of PenumbraBench's results.

    plot_results.py DIR            reads DIR/results.csv, writes DIR/speed_vs_error.png
                                   (and DIR/speed_vs_luminance_error.png from
                                   DIR/results_luminance.csv when it exists)
    plot_results.py CSV PNG        one plot, explicit paths

One panel per scene (scene name and light radius): x = median frame time (log scale), y = mean
absolute error (log scale), one labelled point per method, the averaged_N settings joined as a
series, the cost of rendering without shadows (`none`) as a vertical dashed line, the truth's own error
(seed-to-seed MAE / sqrt(2), from truth.csv) as a dotted horizontal line. In results.csv
the pass's methods are scored on visibility (filled markers) and the others on luminance against
the reference image (hollow markers); see the README next to the CSV.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LUMINANCE_SCORED = ("none", "shadowmap_")
COLOURS = {
    "none": "0.35",
    "shadowmap_1024": "tab:orange",
    "shadowmap_4096": "tab:red",
    "hard_volumes": "tab:purple",
    "wedges": "tab:green",
}
# Label offsets (points) so that neighbouring methods' labels do not overlap.
OFFSETS = {
    "none": (4, 4),
    "shadowmap_1024": (5, -11),
    "shadowmap_4096": (5, 5),
    "hard_volumes": (5, -11),
    "wedges": (5, 5),
}


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key in ("ms_median", "ms_min", "mae", "rmse", "p99", "max", "frac_gt_0.1",
                    "frac_gt_0.5"):
            row[key] = float(row[key])
    return rows


def read_truth_noise(path):
    """scene -> the truth's own error estimate (seed-to-seed MAE / sqrt(2)), from truth.csv."""
    noise = {}
    if not os.path.exists(path):
        return noise
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            try:
                if int(row["noise_pixels"]) > 0:
                    noise[row["scene"]] = float(row["noise_mae"]) / math.sqrt(2.0)
            except (KeyError, ValueError):
                pass
    return noise


def scene_key(name):
    """Orders panels by scene (first appearance is kept by the caller) then radius."""
    match = re.match(r"^(.*)_r([0-9.eE+-]+)$", name)
    if match:
        return match.group(1), float(match.group(2))
    return name, 0.0


def plot(csv_path, png_path, all_luminance=False):
    rows = read_rows(csv_path)
    truth_noise = {} if all_luminance else read_truth_noise(
        os.path.join(os.path.dirname(os.path.abspath(csv_path)), "truth.csv"))
    if not rows:
        print(f"plot_results: {csv_path} has no rows", file=sys.stderr)
        return False
    scenes = []
    for row in rows:
        if row["scene"] not in scenes:
            scenes.append(row["scene"])
    bases = []
    for s in scenes:
        b = scene_key(s)[0]
        if b not in bases:
            bases.append(b)
    per_base = {b: sorted((s for s in scenes if scene_key(s)[0] == b),
                          key=lambda s: scene_key(s)[1]) for b in bases}
    ncols = max(len(v) for v in per_base.values())
    nrows = len(bases)
    fig, axes = plt.subplots(nrows, ncols, figsize=(5.2 * ncols, 3.9 * nrows), squeeze=False)
    for ax in axes.flat:
        ax.set_visible(False)

    for r, base in enumerate(bases):
        for c, scene in enumerate(per_base[base]):
            ax = axes[r][c]
            ax.set_visible(True)
            srows = [row for row in rows if row["scene"] == scene]
            first = srows[0]
            ax.set_title(f"{scene}  ({first['width']}x{first['height']}, "
                         f"{int(first['triangles']):,} tris)", fontsize=10)
            positive = [row["mae"] for row in srows if row["mae"] > 0]
            if scene in truth_noise and truth_noise[scene] > 0:
                positive.append(truth_noise[scene])
            floor = min(positive) / 3 if positive else 1e-4
            for row in srows:
                if row["method"] == "none":
                    ax.axvline(row["ms_median"], color="0.5", linestyle="--", linewidth=1,
                               label="no shadows (cost)")
            if scene in truth_noise and truth_noise[scene] > 0:
                ax.axhline(truth_noise[scene], color="0.6", linestyle=":", linewidth=1)
                ax.annotate("truth noise", (1.0, truth_noise[scene]), xycoords=("axes fraction",
                            "data"), textcoords="offset points", xytext=(-4, 3), ha="right",
                            fontsize=7, color="0.45")
            averaged = sorted((row for row in srows if row["method"].startswith("averaged_")),
                              key=lambda row: int(row["method"].split("_")[1]))
            if averaged:
                ax.plot([row["ms_median"] for row in averaged],
                        [max(row["mae"], floor) for row in averaged], "-o", color="tab:blue",
                        markersize=5, label="averaged_N")
                for row in averaged:
                    ax.annotate(row["method"].split("_")[1],
                                (row["ms_median"], max(row["mae"], floor)),
                                textcoords="offset points", xytext=(4, 4), fontsize=8,
                                color="tab:blue")
            for row in srows:
                method = row["method"]
                if method.startswith("averaged_"):
                    continue
                hollow = (not all_luminance) and method.startswith(LUMINANCE_SCORED)
                colour = COLOURS.get(method, "tab:green")
                ax.plot(row["ms_median"], max(row["mae"], floor), "s" if hollow else "o",
                        markerfacecolor="none" if hollow else colour, markeredgecolor=colour,
                        markersize=7)
                ax.annotate(method, (row["ms_median"], max(row["mae"], floor)),
                            textcoords="offset points", xytext=OFFSETS.get(method, (5, -11)),
                            fontsize=8, color=colour)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("median frame time (ms, log)")
            ax.set_ylabel("MAE (luminance)" if all_luminance else "MAE")
            ax.grid(True, which="both", alpha=0.25)
            # Room for the labels.
            xs = [row["ms_median"] for row in srows if row["ms_median"] > 0]
            if xs:
                ax.set_xlim(min(xs) / 1.5, max(xs) * 3.0)
    if all_luminance:
        title = "PenumbraBench: speed vs error,\nevery method on luminance vs the reference image"
    else:
        title = ("PenumbraBench: speed vs error\nfilled: visibility vs ray-traced truth; "
                 "hollow squares: luminance vs reference image")
    fig.suptitle(title, fontsize=10 if ncols > 1 else 8)
    fig.tight_layout(rect=(0, 0, 1, 1.0 - 0.5 / (3.9 * nrows)))
    fig.savefig(png_path, dpi=110)
    plt.close(fig)
    print(f"wrote {png_path}")
    return True


def main(argv):
    if len(argv) == 2:
        out = argv[1]
        ok = plot(os.path.join(out, "results.csv"), os.path.join(out, "speed_vs_error.png"))
        lum = os.path.join(out, "results_luminance.csv")
        if ok and os.path.exists(lum):
            ok = plot(lum, os.path.join(out, "speed_vs_luminance_error.png"), all_luminance=True)
        return 0 if ok else 1
    if len(argv) == 3:
        return 0 if plot(argv[1], argv[2]) else 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
