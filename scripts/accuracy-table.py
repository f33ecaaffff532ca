#!/usr/bin/env python3
"""Accuracy reports (DIR/report.json of scripts/accuracy-report.sh) as one table, scenes side by
side (the side-by-side record of docs/benchmarks/ is made so): per method the median s/frame with
its minimum-maximum over the rounds, the one-time seconds apart from it (the resampling of
'Resample To Image', the level of detail's build), the time relative to Average (median of the
per-round ratios, +- half their interquartile range), and the mean and worst error against the
exact reference. Prints Markdown.
    python3 scripts/accuracy-table.py "coarse Wavelet" A/report.json "Blunt Fin" B/report.json"""
import json
import sys


def cell(r):
    if r.get("spf") is None:
        return ["%s" % (r.get("note") or "-"), "", "", "", ""]
    t = "%.3f (%.3f-%.3f)" % (r["spf"], r["spf_min"], r["spf_max"])
    once = "-" if r.get("once") is None else "%.3f" % r["once"]
    ratio = "-" if r.get("ratio") is None else "%.2f +-%.0f%%" % (
        r["ratio"], 50 * (r.get("ratio_spread") or 0))
    mean = "-" if r.get("mean") is None else "%.3f" % r["mean"]
    mx = "-" if r.get("max") is None else "%.0f" % r["max"]
    return [t, once, ratio, mean, mx]


def main(argv):
    if len(argv) < 2 or len(argv) % 2:
        raise SystemExit(__doc__)
    scenes = []
    for label, path in zip(argv[0::2], argv[1::2]):
        with open(path) as f:
            scenes.append((label, json.load(f)))
    head = ["method"]
    for label, rep in scenes:
        head += ["%s, %d tets, %d²: s/frame (min-max)" % (label, rep["cells"], rep["size"][0]),
                 "once s", "time / Average", "mean err", "max err"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    names = []  # every scene's rows, in the order they first appear
    for _, rep in scenes:
        names += [r["name"] for r in rep["rows"] if r["name"] not in names]
    for name in names:
        row = [name]
        for _, rep in scenes:
            r = next((x for x in rep["rows"] if x["name"] == name), {})
            row += cell(r)
        lines.append("| " + " | ".join(row) + " |")
    print("\n".join(lines))
    print()
    for label, rep in scenes:
        print("- %s: %s." % (label, rep.get("timing", "")))


if __name__ == "__main__":
    main(sys.argv[1:])
