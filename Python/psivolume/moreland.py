"""Moreland's Table 6.4 (dissertation, section 6.1.2): frame rates of his ray-integration methods
on a Quadro FX 3000 at 800x800, fragment-bound, and its side-by-side with 'Psi Volume'. Both are
shown as frame rates relative to Average Luminance and Attenuation ('Average' here), the only
form in which a 2004 GPU and Mesa's llvmpipe can be compared."""

# frames per second, Moreland's dissertation Table 6.4
TABLE_6_4 = {
    "Blunt Fin": {"Average": 1.314, "Linear Exact": 0.080, "Partial Pre-Integration": 0.937,
                  "Average Opacity": 1.312, "Linear Luminance Average Opacity": 1.196,
                  "Linear Opacity Improved": 0.938},
    "Oxygen Post": {"Average": 0.577, "Linear Exact": 0.028, "Partial Pre-Integration": 0.338,
                    "Average Opacity": 0.599, "Linear Luminance Average Opacity": 0.417,
                    "Linear Opacity Improved": 0.337},
}
# his names for the plugin's methods
HIS_NAME = {"Average": "Average Luminance and Attenuation",
            "Linear Exact": "Linear Luminance and Attenuation",
            "Partial Pre-Integration": "Partial Pre-Integration",
            "Average Opacity": "Average Luminance and Opacity",
            "Linear Luminance Average Opacity": "Linear Luminance, Average Opacity",
            "Linear Opacity Improved": "Linear Luminance and Opacity Approx"}
METHODS = list(HIS_NAME)


def his_relative(model, method):
    """Moreland's frame rate of `method` on `model` over his Average's."""
    t = TABLE_6_4[model]
    return t[method] / t["Average"]


def side_by_side(columns):
    """Markdown: a row per method, Moreland's relative frame rates on both models, then each of
    `columns`, a list of (heading, {method: (time ratio to Average, its spread)}), shown as
    frame-rate ratios (the inverse of the time ratio) with the spread."""
    head = ["method (Moreland's name)", "Blunt Fin, Moreland", "Oxygen Post, Moreland"] + \
        [h for h, _ in columns]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for m in METHODS:
        cells = ["%s (%s)" % (m, HIS_NAME[m]), "%.3f" % his_relative("Blunt Fin", m),
                 "%.3f" % his_relative("Oxygen Post", m)]
        for _, ours in columns:
            r = ours.get(m)
            cells.append("-" if not r or not r[0] else "%.3f +-%.0f%%" % (1.0 / r[0], 50 * r[1]))
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out)
