"""Helpers shared by the plots of bench/plot: errors, colours, labels, saving."""

import math
import os
import textwrap

PIPELINE_COLORS = {
    "octoprox direct": "tab:blue",
    "octoprox amortized": "tab:green",
    "octoprox amortized refined": "tab:olive",
    "FCL default (level 0)": "tab:red",
    "FCL Morton (level 2)": "tab:orange",
    "FCL + OctoMap": "tab:red",
}


class PlotError(Exception):
    """A results file that exists but cannot be plotted."""


def cpu_of(rows):
    cpus = sorted({row.get("cpu", "unknown CPU") for row in rows})
    return ", ".join(cpus)


def color_of(pipeline):
    return PIPELINE_COLORS.get(pipeline)


def save(figure, out_dir, name):
    path = os.path.join(out_dir, name)
    figure.savefig(path, dpi=120)
    print(path)


def plain_log_ticks(axis):
    """Plain numbers (0.2, 100) instead of 2x10^-1 on a log axis; minor ticks
    2, 3, 5 get labels too when the axis spans less than two decades."""
    from matplotlib.ticker import FuncFormatter
    text = lambda v: f"{v:g}"  # noqa: E731
    axis.set_major_formatter(FuncFormatter(lambda v, _: text(v)))
    low, high = axis.get_view_interval()
    short = 0 < low and high / low < 100

    def minor(value, _):
        leading = round(value / 10 ** math.floor(math.log10(value) + 1e-9))
        return text(value) if short and leading in (2, 3, 5) else ""
    axis.set_minor_formatter(FuncFormatter(minor))


def footnote(figure, text, width=190):
    """Grey notes under the axes, each line wrapped at `width` characters."""
    lines = [wrapped for line in text.split("\n") for wrapped in textwrap.wrap(line, width) or [""]]
    figure.text(0.01, 0.005, "\n".join(lines), fontsize=8, color="dimgray", ha="left", va="bottom")

