"""Speedups of octoprox direct over FCL (table2/3/4.json of
`opx-paper-tables --table II/III/IV --json`): plot_tables.png."""

from .common import PlotError, cpu_of, footnote, plain_log_ticks, save

SPEEDUP_PEERS = (("FCL octree", "tab:red"), ("FCL boxes + DynamicAABBTree", "tab:orange"))
OCTOPROX = "octoprox direct"
TABLE_KIND = {"II": "collision", "III": "distance"}


def speedup_groups(rows):
    """[(label, {peer: FCL T_q / octoprox direct T_q})] in file order."""
    cases = {}
    for row in rows:
        key = (row["table"], row["scene"], row["variant"])
        cases.setdefault(key, {})[row["pipeline"]] = row["Tq_ms"]
    groups = []
    for (table, scene, variant), times in cases.items():
        if times.get(OCTOPROX):
            ratios = {p: times[p] / times[OCTOPROX] for p, _ in SPEEDUP_PEERS if p in times}
            kind = TABLE_KIND.get(table, "")
            label = f"{table} {kind}\n{scene} ({variant})" if kind else \
                f"{table} {scene}\n({variant})"
            groups.append((label, ratios))
    return groups


def plot_tables(pyplot, rows, out_dir):
    groups = speedup_groups(rows)
    if not groups:
        raise PlotError("no case with both an FCL pipeline and octoprox direct")
    figure, axes = pyplot.subplots(figsize=(max(10, 0.9 * len(groups) + 2), 6))
    width = 0.8 / len(SPEEDUP_PEERS)
    for i, (peer, color) in enumerate(SPEEDUP_PEERS):
        xs = [g + (i - 0.5) * width for g, (_, r) in enumerate(groups) if peer in r]
        ratios = [r[peer] for _, r in groups if peer in r]
        # bars grow from parity (1), so a case where FCL is faster points down
        axes.bar(xs, [r - 1 for r in ratios], width, bottom=1, color=color,
                 label=f"{peer} T_q / octoprox direct T_q")
        for x, ratio in zip(xs, ratios):
            above = ratio >= 1
            axes.text(x, ratio * (1.08 if above else 0.93), f"{ratio:.3g}", ha="center",
                      va="bottom" if above else "top", fontsize=7, rotation=90)
    axes.axhline(1.0, color="black", linewidth=1)
    axes.set_yscale("log")
    values = [v for _, ratios in groups for v in ratios.values()]
    axes.set_ylim(min(min(values) / 2, 0.5), max(values) * 4)
    axes.set_xticks(range(len(groups)))
    axes.set_xticklabels([label for label, _ in groups], fontsize=8)
    axes.set_ylabel("speedup of octoprox direct (> 1: octoprox faster)")
    plain_log_ticks(axes.yaxis)
    axes.grid(True, axis="y", which="both", alpha=0.3)
    axes.legend(fontsize=9, loc="upper left")
    figure.suptitle(f"Paper Tables II-IV: query time of FCL over octoprox direct "
                    f"({cpu_of(rows)})")
    footnote(figure, "Queries only: FCL boxes also pay a build T_1 per map (octoprox "
             "direct: none). Scenes H/F: synthetic, 300 objects (H: some collide, F: none "
             "do); (a) primitives, (b) meshes; IV: PR2 on a real RGB-D frame.\n"
             "Source: opx-paper-tables --table II/III/IV --json")
    figure.tight_layout(rect=(0, 0.05, 1, 1))
    save(figure, out_dir, "plot_tables.png")
