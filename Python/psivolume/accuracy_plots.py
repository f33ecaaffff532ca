"""Outputs of the accuracy report (accuracy.report): the table as text and Markdown, the
error-against-time plot (accuracy.png) and the images with their error maps (methods.png).
Uses matplotlib when it imports; otherwise writes the plots with the project's PNG writer
(images.write_png: plain points and images, no text) and says so in report.md."""
import json
import math
import os
import textwrap

import numpy as np

from . import moreland
from .images import write_png

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    HAVE_MATPLOTLIB = True
except ImportError:  # pragma: no cover - depends on the ParaView build
    HAVE_MATPLOTLIB = False

HEADER = ("method", "s/frame", "min-max", "CPU s/frame", "once s", "time / Average", "mean err",
          "max err", "mean err x s")
EXPLAIN = ("Times are medians over interleaved rounds (every method and mapper once per round, "
           "the order rotating), with their minimum and maximum over the rounds; CPU s/frame is "
           "the CPU time of the drawing process (all its threads) per frame; 'time / Average' is "
           "the ratio to Average taken round by round, its median and interquartile spread. "
           "'once s' is a one-time cost outside the frame times: the first frame of 'Resample To "
           "Image' (the resampling of the mesh to its sampling dimensions), the build of the "
           "level of detail for the interactive image of 'Psi Volume' (InteractionMode 'Volume "
           "LOD', timed with interactive renders). "
           "Errors are absolute differences of 8-bit RGB channels (0..255) against the exact "
           "reference at the same view, mean over all pixels and channels, and the worst one. "
           "'mean err x s' is the mean error times the frame time: lower is better on both "
           "counts (a method twice as fast at twice the error scores the same).")


def _fmt(v, spec):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else spec % v


def _ratio(r):
    if r.get("ratio") is None:
        return "-"
    return "%.3f +-%.1f%%" % (r["ratio"], 50 * r["ratio_spread"])


def table_rows(rows):
    return [(r["name"], _fmt(r["spf"], "%.3f"),
             "-" if r.get("spf_min") is None else "%.3f-%.3f" % (r["spf_min"], r["spf_max"]),
             _fmt(r.get("cpu"), "%.3f"), _fmt(r.get("once"), "%.3f"), _ratio(r),
             _fmt(r["mean"], "%.3f"),
             _fmt(r["max"], "%.0f"), _fmt(r["err_s"], "%.3f"), r["note"]) for r in rows]


def table_text(rows, info):
    lines = ["", "%s: %d cells, %dx%d, %d timed frames per method and round" % (
        info["title"], info["cells"], info["size"][0], info["size"][1], info["frames"])]
    if info.get("timing"):
        lines.append(info["timing"])
    lines.append("%-44s %8s %13s %11s %8s %15s %9s %7s %12s" % HEADER)
    for row in table_rows(rows):
        lines.append("%-44s %8s %13s %11s %8s %15s %9s %7s %12s %s" % row)
    return "\n".join(lines)


def table_markdown(rows):
    out = ["| " + " | ".join(HEADER) + " | note |", "|" + "---|" * (len(HEADER) + 1)]
    for row in table_rows(rows):
        out.append("| " + " | ".join(row) + " |")
    return "\n".join(out)


def write_all(rows, ref, info, out_dir):
    plotted = plot_accuracy(rows, info, os.path.join(out_dir, "accuracy.png"))
    plot_methods(rows, ref, os.path.join(out_dir, "methods.png"))
    with open(os.path.join(out_dir, "report.md"), "w", encoding="utf-8") as f:  # any array name
        f.write("# What accuracy costs: %s\n\n" % info["title"])
        f.write("%d cells, %dx%d pixels, %d timed frames per method and round (after a warm-up "
                "frame), llvmpipe threads: %s. %s\n\n%s.\n\n" % (
                    info["cells"], info["size"][0], info["size"][1], info["frames"],
                    info.get("threads", "all"), EXPLAIN, info.get("timing", "")))
        f.write(table_markdown(rows) + "\n\n")
        f.write(moreland_section(rows, info) + "\n\n")
        if not plotted:
            f.write("matplotlib is not available in this pvpython: accuracy.png and methods.png "
                    "were written without labels (VTK's PNG writer).\n\n")
        f.write("![error against time](accuracy.png)\n\n![images and error maps](methods.png)\n")
    with open(os.path.join(out_dir, "report.json"), "w") as f:
        json.dump(dict(info, rows=[{k: (None if isinstance(v, float) and math.isnan(v) else v)
                                    for k, v in r.items() if k != "image"} for r in rows]),
                  f, indent=1)
    print("report: %s" % os.path.abspath(os.path.join(out_dir, "report.md")))


def moreland_section(rows, info):
    """Moreland's Table 6.4 beside this report's ratios (frame rates relative to Average)."""
    ours = {r["name"]: (r.get("ratio"), r.get("ratio_spread") or 0.0) for r in rows}
    heading = "this scene, llvmpipe threads: %s" % info.get("threads", "all")
    return ("Frame rate relative to Average, beside Moreland's Table 6.4 (Quadro FX 3000, "
            "800x800; ours with the spread of the ratio over the rounds):\n\n" +
            moreland.side_by_side([(heading, ours)]))


def _spread(targets, gap):
    """Positions near `targets` (sorted ascending, in [0, 1]) at least `gap` apart."""
    pos = []
    for t in targets:
        pos.append(max(t, pos[-1] + gap) if pos else max(t, 0.0))
    for i in range(len(pos) - 1, -1, -1):
        upper = 1.0 if i == len(pos) - 1 else pos[i + 1] - gap
        pos[i] = min(pos[i], upper)
    return pos


# matplotlib's "tab10" colors (RGB 0..1), for the methods of 'Psi Volume'.
TAB10 = [(0.122, 0.467, 0.706), (1.0, 0.498, 0.055), (0.173, 0.627, 0.173),
         (0.839, 0.153, 0.157), (0.580, 0.404, 0.741), (0.549, 0.337, 0.294),
         (0.890, 0.467, 0.761), (0.498, 0.498, 0.498), (0.737, 0.741, 0.133),
         (0.090, 0.745, 0.812)]
NAMED_COLORS = dict(black=(0.0, 0.0, 0.0), dimgray=(0.412, 0.412, 0.412),
                    darkorange=(1.0, 0.549, 0.0), crimson=(0.863, 0.078, 0.235))


def point_style(name):
    """How a row's point is drawn (here and in the GUI's chart, psivolume.gui): (marker, RGB,
    area in square points, matplotlib's scatter size). ParaView's mappers in black and gray
    squares and diamonds, the interactive image an orange cross, the reference a red star, each
    method of 'Psi Volume' a color of its own, a circle without adaptive sampling and a triangle
    with it."""
    if name.startswith("ParaView Resample"):
        return "diamond", NAMED_COLORS["dimgray"], 36
    if name.startswith("ParaView"):
        return "square", NAMED_COLORS["black"], 36
    if name.endswith("(interactive)"):
        return "cross", NAMED_COLORS["darkorange"], 70
    if name.startswith("Exact"):
        return "star", NAMED_COLORS["crimson"], 120
    base = name.replace(" + adaptive", "")
    color = TAB10[sum(map(ord, base)) % 10]
    return ("triangle" if "adaptive" in name else "circle"), color, 36


MPL_MARKERS = dict(diamond="D", square="s", cross="P", star="*", triangle="^", circle="o")


def _style(name):
    marker, color, area = point_style(name)
    return dict(marker=MPL_MARKERS[marker], color=color, s=area)


def plotted(rows):
    """The rows of the error-against-time plot: those with a frame time and an error."""
    return [r for r in rows if r["spf"] is not None and not math.isnan(r["spf"])
            and not math.isnan(r["mean"])]


def error_floor(pts):
    """Where an error of 0 (the reference against itself) is drawn on the logarithmic axis: a
    third of the smallest other error."""
    positive = [r["mean"] for r in pts if r["mean"] > 0] or [1.0]
    return min(positive) / 3.0


def point_label(r):
    return r["name"] + (" (error 0)" if r["mean"] == 0 else "")


def plot_accuracy(rows, info, path):
    """Mean error against seconds per frame, both logarithmic; labels in a column to the right of
    the axes, in the order of their points and joined to them, so that none overlap."""
    pts = plotted(rows)
    if not HAVE_MATPLOTLIB:
        return _fallback_scatter(pts, path)
    floor = error_floor(pts)
    fig, ax = plt.subplots(figsize=(8.6, 0.26 * len(pts) + 2.2))
    fig.subplots_adjust(left=0.1, right=0.56, top=0.9, bottom=0.12)
    for r in pts:
        st = _style(r["name"])
        ax.scatter(r["spf"], max(r["mean"], floor), zorder=3, **st)
        if r.get("spf_min") is not None and r["spf_max"] > r["spf_min"]:
            # the spread of the frame time over the rounds
            ax.errorbar(r["spf"], max(r["mean"], floor), xerr=[[r["spf"] - r["spf_min"]],
                        [r["spf_max"] - r["spf"]]], fmt="none", ecolor=st["color"], lw=1,
                        capsize=2, zorder=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    xs = [r["spf"] for r in pts]
    ys = [max(r["mean"], floor) for r in pts]
    ax.set_xlim(min(xs) / 1.5, max(xs) * 1.5)
    ax.set_ylim(floor / 1.5, max(ys) * 1.5)
    ax.set_xlabel("seconds per frame (%dx%d, llvmpipe)" % tuple(info["size"]))
    ax.set_ylabel("mean error vs exact reference (0..255)")
    # (the title names the array, as it is: a dollar sign in it is not matplotlib's math)
    ax.set_title(info["title"].replace("$", r"\$"), fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    to_axes = ax.transAxes.inverted()
    order = sorted(pts, key=lambda r: to_axes.transform(
        ax.transData.transform((r["spf"], max(r["mean"], floor))))[1])
    targets = [to_axes.transform(ax.transData.transform((r["spf"], max(r["mean"], floor))))[1]
               for r in order]
    slots = _spread(targets, min(0.9 / max(len(order), 1), 0.07))
    for r, y in zip(order, slots):
        ax.annotate(point_label(r), xy=(r["spf"], max(r["mean"], floor)), xycoords="data",
                    xytext=(1.04, y), textcoords="axes fraction", fontsize=8, va="center",
                    arrowprops=dict(arrowstyle="-", color="0.6", lw=0.6, shrinkA=0, shrinkB=3))
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return True


def plot_methods(rows, ref, path, pairs_per_line=4):
    """Each image beside its error map (|image - reference|, mean over RGB, one color scale)."""
    shown = [dict(name="Exact reference (CPU) image", image=ref, mean=0.0)] + [
        r for r in rows if r["image"] is not None and not r["name"].startswith("Exact")]
    if not HAVE_MATPLOTLIB:
        return _fallback_tiles(shown, ref, path)
    emax = max(8.0, max(float(np.percentile(np.abs(r["image"] - ref).mean(axis=2), 99.5))
                        for r in shown))
    lines = int(math.ceil(len(shown) / float(pairs_per_line)))
    fig, axes = plt.subplots(lines, 2 * pairs_per_line,
                             figsize=(2 * pairs_per_line * 1.45, lines * 1.85 + 0.5))
    axes = np.atleast_2d(axes)
    for a in axes.flat:
        a.axis("off")
    im = None
    for k, r in enumerate(shown):
        a, b = axes[k // pairs_per_line, 2 * (k % pairs_per_line)], \
            axes[k // pairs_per_line, 2 * (k % pairs_per_line) + 1]
        a.imshow(np.clip(r["image"], 0, 255).astype(np.uint8), origin="lower")
        im = b.imshow(np.abs(r["image"] - ref).mean(axis=2), origin="lower", cmap="magma",
                      vmin=0, vmax=emax)
        a.set_title(textwrap.fill(r["name"].replace("ParaView ", "ParaView\n"), 22,
                                  break_long_words=False, replace_whitespace=False), fontsize=7)
        b.set_title("error, mean %.2f" % r["mean"], fontsize=7)
    fig.subplots_adjust(left=0.01, right=0.92, top=0.93, bottom=0.02, wspace=0.05, hspace=0.45)
    cax = fig.add_axes([0.935, 0.1, 0.012, 0.75])
    fig.colorbar(im, cax=cax).set_label("|error| (0..255)", fontsize=7)
    cax.tick_params(labelsize=7)
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return True


def _fallback_scatter(pts, path, n=400):
    """Without matplotlib: log-log points on white, no text."""
    canvas = np.full((n, n, 3), 255, np.uint8)
    if pts:
        x = np.log10([r["spf"] for r in pts])
        y = np.log10([max(r["mean"], 1e-3) for r in pts])
        fx = (x - x.min()) / max(np.ptp(x), 1e-9) * (n - 40) + 20
        fy = (y - y.min()) / max(np.ptp(y), 1e-9) * (n - 40) + 20
        for i, j in zip(fx.astype(int), fy.astype(int)):
            canvas[j - 3:j + 4, i - 3:i + 4] = (30, 60, 200)
    write_png(canvas, path)
    return False


def _fallback_tiles(shown, ref, path):
    tiles = []
    for r in shown:
        err = np.clip(np.abs(r["image"] - ref).mean(axis=2, keepdims=True) * 8, 0, 255)
        tiles.append(np.concatenate([np.clip(r["image"], 0, 255), np.repeat(err, 3, 2)], 1))
    write_png(np.concatenate(tiles, 0), path)
    return False
