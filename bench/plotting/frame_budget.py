"""The per-frame budget (frame_bench.json of `opx-frame-bench --json`):
plot_frame_budget.png."""

from .common import PlotError, footnote, save

FRAME_PERIOD_MS = 1000.0 / 30.0
FRAME_STAGES = (("structure", "structure (tree of boxes)", "tab:purple"),
                ("pose_update", "pose update", "tab:blue"),
                ("collision_queries", "collision queries", "tab:orange"),
                ("distance_queries", "distance queries", "tab:red"))
INGEST_COLOR = "0.65"
INGEST_PANELS = (("ingest_raycast", "total", "ray-cast ingest (free + occupied cells)"),
                 ("ingest_endpoints", "total_endpoints_ingest", "endpoint-only ingest"),
                 (None, None, "no ingest: structure, pose updates and queries only (zoomed)"))
ZOOMED_CEILING_MS = 6 * 1000.0 / 30.0
SHORT_PIPELINE = {"octoprox direct": "direct", "octoprox amortized": "amortized",
                  "FCL + OctoMap": "FCL"}


def frame_bars(frame_bench):
    """[(x, run, pipeline entry)] and [(group centre, group label)]."""
    bars, groups, x = [], [], 0.0
    for run in frame_bench["runs"]:
        first = x
        for entry in run["pipelines"]:
            bars.append((x, run, entry))
            x += 1.0
        frames = run["frames"]
        groups.append(((first + x - 1.0) / 2, f"{run['stream']}, {run['resolution'] * 100:g}"
                       f" cm\n{frames} frame{'' if frames == 1 else 's'}"))
        x += 0.8
    return bars, groups


def frame_ceiling(bars):
    """A y limit that shows every non-ingest stack and the 33 ms line whole."""
    highest = max(sum(e[s]["median_ms"] for s, _, _ in FRAME_STAGES) for _, _, e in bars)
    return max(3.5 * FRAME_PERIOD_MS, 1.15 * highest)


def draw_frame_bar(axes, x, entry, ingest_key, total_key, ceiling):
    bottom = 0.0
    ingest = ((ingest_key, "ingest", INGEST_COLOR),) if ingest_key else ()
    for key, _, color in FRAME_STAGES + ingest:
        height = entry[key]["median_ms"]
        if min(height, max(ceiling - bottom, 0)) > 0:
            axes.bar(x, min(height, max(ceiling - bottom, 0)), 0.8, bottom=bottom,
                     color=color, edgecolor="white", linewidth=0.5)
        bottom += height
    # Without ingest: the sum of the stage medians.
    total = entry[total_key]["median_ms"] if total_key else bottom
    text = f"{total:.0f} ms" if total >= 10 else f"{total:.1f} ms"
    if entry.get("distance_scaled"):
        text += "*"
    if bottom > ceiling:
        text = "\u2191 " + text
    inside = bottom > 0.8 * ceiling  # no room above the bar: write inside its top
    axes.text(x, min(bottom, ceiling) - ceiling * 0.01 if inside else bottom + ceiling * 0.01,
              text, rotation=90, ha="center", va="top" if inside else "bottom", fontsize=8,
              color="white" if inside else "black", fontweight="bold" if inside else None)


def draw_frame_panel(axes, bars, groups, panel, ceiling):
    ingest_key, total_key, title = panel
    for x, _, entry in bars:
        draw_frame_bar(axes, x, entry, ingest_key, total_key, ceiling)
    axes.axhline(FRAME_PERIOD_MS, color="black", linestyle="--", linewidth=1)
    axes.text(bars[-1][0] + 0.55, FRAME_PERIOD_MS, "33 ms\n(30 Hz)", va="center", fontsize=8)
    axes.set_ylim(0, ceiling)
    axes.set_xlim(-0.7, bars[-1][0] + 1.6)
    axes.set_xticks([x for x, _, _ in bars], minor=True)
    axes.set_xticklabels([SHORT_PIPELINE.get(e["pipeline"], e["pipeline"])
                          for _, _, e in bars], minor=True)
    axes.set_xticks([c for c, _ in groups])
    axes.set_xticklabels([label for _, label in groups])
    axes.xaxis.remove_overlapping_locs = False  # keep the pipeline under a group's centre
    axes.tick_params(axis="x", which="minor", labelsize=8)
    axes.tick_params(axis="x", which="major", length=0, pad=16, labelsize=9)
    axes.set_ylabel("median time per frame [ms]")
    axes.set_title(f"Frame with {title}")
    axes.grid(True, axis="y", alpha=0.3)


def frame_legend(figure, pyplot):
    handles = [pyplot.Rectangle((0, 0), 1, 1, color=c) for _, _, c in FRAME_STAGES]
    handles.append(pyplot.Rectangle((0, 0), 1, 1, color=INGEST_COLOR))
    labels = [label for _, label, _ in FRAME_STAGES]
    labels.append("ingest (top: ray-cast, middle: endpoints)")
    figure.legend(handles, labels, loc="upper center", ncol=5, fontsize=9,
                  bbox_to_anchor=(0.5, 0.945))


def frame_note(frame_bench, bars):
    note = ("Bars: sum of the per-stage medians, bottom to top in the legend's order; "
            "label: median of the per-frame totals (bottom panel: sum of the stage medians; "
            "\u2191: bar cut at the top). "
            "FCL = FCL + OctoMap.\n")
    scaled = [(run, e) for _, run, e in bars if e.get("distance_scaled")]
    if scaled:
        run, _ = scaled[0]
        note += (f"* distance stage measured on {run.get('fcl_distance_queries_measured')} "
                 f"of {run['distance_queries']} queries and scaled (see the JSON per run). ")
    if frame_bench.get("quick"):
        note += "QUICK RUN (--quick): few frames and queries. "
    return note + "Source: opx-frame-bench --json"


def query_counts(frame_bench):
    counts = {(r["collision_queries"], r["distance_queries"]) for r in frame_bench["runs"]}
    if len(counts) != 1:
        return " (query counts per run: see the JSON)"
    collision, distance = counts.pop()
    return f" ({collision} collision, {distance} distance per frame)"


def plot_frame_budget(pyplot, frame_bench, out_dir):
    bars, groups = frame_bars(frame_bench)
    if not bars:
        raise PlotError("no runs with pipelines")
    ceiling = frame_ceiling(bars)
    figure, panels = pyplot.subplots(3, 1, figsize=(max(10, 0.55 * len(bars) + 3), 14))
    for axes, panel in zip(panels, INGEST_PANELS):
        draw_frame_panel(axes, bars, groups, panel, ceiling if panel[0] else ZOOMED_CEILING_MS)
    figure.suptitle("Per-frame budget: one sensor frame, then pose update and queries"
                    f"{query_counts(frame_bench)}\n{frame_bench.get('cpu', 'unknown CPU')}",
                    x=0.01, ha="left")
    frame_legend(figure, pyplot)
    footnote(figure, frame_note(frame_bench, bars))
    figure.tight_layout(rect=(0, 0.04, 1, 0.955))
    save(figure, out_dir, "plot_frame_budget.png")
