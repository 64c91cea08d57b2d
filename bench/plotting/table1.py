"""Paper Table I (table1.json of `opx-paper-tables --table I --json`):
plot_break_even.png and plot_scaling.png."""

import math

from .common import color_of, cpu_of, footnote, plain_log_ticks, save

PAPER_CELLS = 7784
TQ_POINTS = (("Tq_first_ms", 1), ("Tq_10_ms", 10), ("Tq_100_ms", 100), ("Tq_1000_ms", 1000))


def build_ms(row):
    return row["T11_ms"] + row["T12_ms"]


def measured_tq(row):
    """[(N, mean T_q of the first N queries)] for the N that were measured."""
    return [(n, row[key]) for key, n in TQ_POINTS if row.get(key) is not None]


def tq_average(points, n):
    """Mean T_q of the first n queries, linear in log n between measured points."""
    for (n0, t0), (n1, t1) in zip(points, points[1:]):
        if n0 <= n <= n1:
            w = math.log(n / n0) / math.log(n1 / n0)
            return t0 + w * (t1 - t0)
    return points[0][1] if n <= points[0][0] else None


def cumulative_cost(row, counts):
    points = measured_tq(row)
    return [build_ms(row) + n * tq_average(points, n) for n in counts]


def break_even(cost, reference, counts):
    """The first N at which cost <= reference, or None."""
    return next((n for n, a, b in zip(counts, cost, reference) if a <= b), None)


def paper_map_rows(table1):
    cells = PAPER_CELLS if any(r["cells"] == PAPER_CELLS for r in table1) \
        else min(r["cells"] for r in table1)
    return cells, [r for r in table1 if r["cells"] == cells]


def draw_cumulative(axes, rows):
    costs = {}
    for row in rows:
        last_n = measured_tq(row)[-1][0]
        counts = list(range(1, last_n + 1))
        costs[row["pipeline"]] = cumulative_cost(row, counts)
        axes.plot(counts, costs[row["pipeline"]], label=row["pipeline"],
                  color=color_of(row["pipeline"]))
        marks = [n for n, _ in measured_tq(row)]
        axes.plot(marks, [costs[row["pipeline"]][n - 1] for n in marks], "o",
                  color=color_of(row["pipeline"]), markersize=4)
    direct = costs.get("octoprox direct")
    amortized = costs.get("octoprox amortized")
    if direct and amortized:
        n = break_even(amortized, direct, range(1, min(len(direct), len(amortized)) + 1))
        if n is not None:
            axes.axvline(n, color="tab:green", linestyle=":", linewidth=1)
            axes.annotate(f"amortized beats direct\nfrom N \u2248 {n} queries\n(interpolated)",
                          xy=(n, amortized[n - 1]), xytext=(n * 2.2, amortized[n - 1] / 4),
                          arrowprops={"arrowstyle": "->", "color": "tab:green"},
                          fontsize=9, color="tab:green")
    finish_log_axes(axes, "cumulative time T_1 + N T_q(N) [ms]", "Cumulative cost of N queries")


def finish_log_axes(axes, ylabel, title):
    """Log-log axes against N, plain tick labels, grid and legend."""
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("queries N after one build")
    axes.set_ylabel(ylabel)
    axes.set_title(title)
    plain_log_ticks(axes.xaxis)
    plain_log_ticks(axes.yaxis)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)


def draw_tq_average(axes, rows):
    for row in rows:
        points = measured_tq(row)
        counts = list(range(1, points[-1][0] + 1))
        axes.plot(counts, [tq_average(points, n) for n in counts],
                  label=row["pipeline"], color=color_of(row["pipeline"]))
        axes.plot(*zip(*points), "o", color=color_of(row["pipeline"]), markersize=4)
    finish_log_axes(axes, "mean query time T_q(N) of the first N queries [ms]",
                    "Mean query time (the tree refines as queries run)")


def plot_break_even(pyplot, table1, out_dir):
    cells, rows = paper_map_rows(table1)
    figure, (left, right) = pyplot.subplots(1, 2, figsize=(13, 5.5))
    draw_cumulative(left, rows)
    draw_tq_average(right, rows)
    figure.suptitle(f"Paper Table I: break-even of a build, {cells:,} occupied cells, "
                    f"collision of 300 objects ({cpu_of(rows)})")
    footnote(figure, "Dots: measured (mean of the first 1, 10, 100, 1000 queries); lines "
             "interpolate T_q(N) linearly in log N. T_1 = T_{1,1} + T_{1,2} (octoprox "
             "direct: 0). Source: opx-paper-tables --table I --json table1.json")
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    save(figure, out_dir, "plot_break_even.png")


ROOM_MAP = "room 2 cm"


def is_room(row):
    """A row of the 2 cm Kinect-like frame (a real-looking map, not random cells)."""
    return row.get("map") == ROOM_MAP


def scaling_tq(row):
    """(N, T_q) at the largest N measured for the row."""
    return measured_tq(row)[-1]


def by_pipeline(rows):
    grouped = {}
    for row in sorted(rows, key=lambda r: r["cells"]):
        grouped.setdefault(row["pipeline"], []).append(row)
    return grouped


def draw_scaling(axes, grouped, value, ylabel, title, split_by_contact):
    """One line per pipeline; with split_by_contact, rows whose queries hit
    nothing (full traversal, hollow markers) are not joined to rows whose
    queries stop at the first contact: the two are different workloads."""
    for pipeline, rows in grouped.items():
        label = pipeline
        for kind in ((False, True) if split_by_contact else (None,)):
            points = [(r["cells"], value(r)) for r in rows if value(r) > 0 and not is_room(r)
                      and (kind is None or bool(r.get("collided")) == kind)]
            if points:
                axes.plot(*zip(*points), "o-", color=color_of(pipeline), label=label,
                          markerfacecolor="white" if kind is False else None)
                label = None
        room = [(r["cells"], value(r)) for r in rows if value(r) > 0 and is_room(r)]
        if room:  # another kind of map: a star, not a point of the line
            axes.plot(*zip(*room), "*", color=color_of(pipeline), markersize=11)
    if any(is_room(r) for rows in grouped.values() for r in rows):
        axes.plot([], [], "*", color="gray", markersize=11, label=f"{ROOM_MAP} frame (stars)")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("occupied cells")
    axes.set_ylabel(ylabel)
    axes.set_title(title)
    plain_log_ticks(axes.yaxis)
    # ticks at the measured map sizes only
    axes.set_xticks(sorted({r["cells"] for rows in grouped.values() for r in rows if not is_room(r)}))
    axes.xaxis.set_major_formatter("{x:,.0f}")
    axes.xaxis.set_minor_formatter("")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)


def scaling_note(table1):
    used = {}
    for row in table1:
        used.setdefault(scaling_tq(row)[0], set()).add(row["cells"])
    tq = "; ".join(f"first {n} at {', '.join(f'{c:,}' for c in sorted(cells))} cells"
                   for n, cells in sorted(used.items(), reverse=True))
    collided = sorted({r["cells"] for r in table1 if r.get("collided")})
    note = f"T_q = mean of the {tq}."
    if collided:
        note += (f" At {', '.join(f'{c:,}' for c in collided)} cells the objects collide, "
                 "so a query stops at its first contact (not a full traversal).")
    room = sorted({r["cells"] for r in table1 if is_room(r)})
    if room:
        note += (f" Stars: the generated room ray-cast at 2 cm ({room[0]:,} cells), "
                 "objects at a tenth of their size.")
    return note


def plot_scaling(pyplot, table1, out_dir):
    grouped = by_pipeline(table1)
    figure, (left, right) = pyplot.subplots(1, 2, figsize=(13, 5.5))
    draw_scaling(left, grouped, lambda r: scaling_tq(r)[1], "query time T_q [ms]",
                 "Query time against map size (hollow: no contact, full traversal)",
                 split_by_contact=True)
    draw_scaling(right, grouped, build_ms, "build time T_1 = T_{1,1} + T_{1,2} [ms]",
                 "Build time against map size (octoprox direct: none)",
                 split_by_contact=False)
    figure.suptitle(f"Paper Table I: scaling with occupied cells, collision of 300 objects "
                    f"({cpu_of(table1)})")
    footnote(figure, scaling_note(table1) + "\nSource: opx-paper-tables --table I "
             "--json table1.json")
    figure.tight_layout(rect=(0, 0.07, 1, 1))
    save(figure, out_dir, "plot_scaling.png")
