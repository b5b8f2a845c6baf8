#!/usr/bin/env python3
"""The report of a `penumbra study`: plots and an HTML page from its folder.

    python3 scripts/study_report.py STUDY_DIR [--budget-ms MS]

Reads STUDY_DIR/results.csv (the rows) and results.json (the device, the
reference, the per-point summaries with their preview images) and writes
into STUDY_DIR:
  error_vs_time.png  log-log mean relMSE against mean GPU time per technique,
                     the Pareto front and the time budget
  error_vs_spp.png   mean relMSE against spp with each technique's fitted slope
  report.html        the plots, the equal-time grid (the reference and each
                     technique at the most samples that fit the budget), and
                     tables: one row per technique, one per point
Needs python3-matplotlib (Debian).
"""
import argparse
import csv
import html
import json
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("study_report.py: matplotlib is missing (Debian: apt install python3-matplotlib)")


def mean(values):
    return sum(values) / len(values)


def load(folder):
    with open(os.path.join(folder, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"study_report.py: {folder}/results.csv has no rows")
    with open(os.path.join(folder, "results.json")) as f:
        doc = json.load(f)
    return rows, doc


def summaries(rows):
    """(technique, spp) -> mean GPU ms, mean relMSE, over the seeds, in CSV order."""
    groups = {}
    for r in rows:
        key = (r["technique"], int(r["spp"]))
        groups.setdefault(key, []).append((float(r["gpu_ms"]), float(r["relmse"])))
    return {k: (mean([v[0] for v in g]), mean([v[1] for v in g]), len(g)) for k, g in groups.items()}


def techniques(points):
    order = []
    for technique, _ in points:
        if technique not in order:
            order.append(technique)
    return order


def slope(points, technique):
    xs, ys = [], []
    for (t, spp), (_, rel, _) in points.items():
        if t == technique and rel > 0:
            xs.append(math.log(spp))
            ys.append(math.log(rel))
    if len(set(xs)) < 2:
        return None
    mx, my = mean(xs), mean(ys)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return b, my - b * mx


def pareto(points):
    front = []
    for k, (ms, rel, _) in points.items():
        dominated = any(
            (o[0] <= ms and o[1] <= rel) and (o[0] < ms or o[1] < rel)
            for j, o in points.items() if j != k)
        if not dominated:
            front.append(k)
    return sorted(front, key=lambda k: points[k][0])


def plot_error_vs_time(points, budget, path):
    fig, ax = plt.subplots(figsize=(7, 5))
    for t in techniques(points):
        keys = sorted([k for k in points if k[0] == t], key=lambda k: k[1])
        ax.plot([points[k][0] for k in keys], [points[k][1] for k in keys], "o-", label=t)
    front = pareto(points)
    ax.plot([points[k][0] for k in front], [points[k][1] for k in front], "k--", lw=1,
            label="Pareto front")
    ax.axvline(budget, color="grey", ls=":", label=f"budget {budget:g} ms")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("GPU time per image (ms)")
    ax.set_ylabel("relMSE (mean over seeds)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_error_vs_spp(points, path):
    fig, ax = plt.subplots(figsize=(7, 5))
    for t in techniques(points):
        keys = sorted([k for k in points if k[0] == t], key=lambda k: k[1])
        fit = slope(points, t)
        label = t if fit is None else f"{t} (slope {fit[0]:+.2f})"
        ax.plot([k[1] for k in keys], [points[k][1] for k in keys], "o-", label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel("relMSE (mean over seeds)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def write_html(folder, rows, doc, points, budget):
    e = html.escape
    images = {(s["technique"], s["spp"]): s.get("image") for s in doc.get("summaries", [])}
    ref = doc.get("reference", {})
    noise = ref.get("noiseRelMse")
    out = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'>",
        f"<title>Penumbra study: {e(doc.get('scene', ''))}</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:1100px}"
        "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
        "text-align:right}td:first-child,th:first-child{text-align:left}"
        ".grid{display:flex;flex-wrap:wrap;gap:12px}.grid figure{margin:0}"
        ".grid img{width:240px;image-rendering:pixelated}</style></head><body>",
        f"<h1>Study: {e(doc.get('scene', ''))}, {doc.get('width')}x{doc.get('height')}</h1>",
        f"<p>Device: {e(doc.get('device', ''))} ({e(doc.get('api', ''))}, {e(doc.get('backend', ''))}),"
        f" commit {e(doc.get('commit', ''))}. Reference: {e(str(ref.get('source', '')))}"
        + (f", {ref.get('spp')} spp" if ref.get("spp") else "")
        + (f", its own relMSE about {noise:.3e}" if noise is not None else ", its noise unknown")
        + ".</p>",
    ]
    best = [k for k in points if points[k][0] <= budget]
    if best:
        k = min(best, key=lambda k: points[k][1])
        out.append(f"<p id='answer'>Within {budget:g} ms the lowest error is <b>{e(k[0])}</b> at "
                   f"{k[1]} spp: relMSE {points[k][1]:.3e} in {points[k][0]:.3f} ms.</p>")
    else:
        out.append(f"<p id='answer'>No point of the study fits in {budget:g} ms.</p>")
    out.append("<h2>Error against time</h2><img src='error_vs_time.png' alt='error vs time'>")
    out.append("<h2>Error against samples</h2><img src='error_vs_spp.png' alt='error vs spp'>")
    out.append(f"<h2>At equal time ({budget:g} ms)</h2><div class='grid'>")
    out.append("<figure><img src='reference.png' alt='reference'><figcaption>reference"
               "</figcaption></figure>")
    for t in techniques(points):
        fits = [k for k in points if k[0] == t and points[k][0] <= budget]
        if not fits:
            continue
        k = max(fits, key=lambda k: k[1])
        if images.get(k):
            out.append(f"<figure><img src='{e(images[k])}' alt='{e(t)}'><figcaption>{e(t)}, "
                       f"{k[1]} spp, relMSE {points[k][1]:.2e}</figcaption></figure>")
    out.append("</div><h2>Techniques</h2><table id='techniques'><tr><th>technique</th>"
               "<th>convergence slope</th><th>best within budget</th><th>relMSE</th>"
               "<th>GPU ms</th></tr>")
    for t in techniques(points):
        fit = slope(points, t)
        fits = [k for k in points if k[0] == t and points[k][0] <= budget]
        k = min(fits, key=lambda k: points[k][1]) if fits else None
        out.append(
            f"<tr><td>{e(t)}</td><td>{'' if fit is None else f'{fit[0]:+.3f}'}</td>"
            f"<td>{'' if k is None else f'{k[1]} spp'}</td>"
            f"<td>{'' if k is None else f'{points[k][1]:.3e}'}</td>"
            f"<td>{'' if k is None else f'{points[k][0]:.3f}'}</td></tr>")
    out.append("</table><h2>Points (means over seeds)</h2><table id='points'><tr><th>technique"
               "</th><th>spp</th><th>seeds</th><th>GPU ms</th><th>relMSE</th></tr>")
    for (t, spp), (ms, rel, n) in points.items():
        out.append(f"<tr><td>{e(t)}</td><td>{spp}</td><td>{n}</td><td>{ms:.3f}</td>"
                   f"<td>{rel:.3e}</td></tr>")
    # Marks the page once every image has loaded (or failed): what a
    # headless browser checks.
    out.append("</table><script>window.addEventListener('load',()=>{const i=[...document.images];"
               "document.body.dataset.images=i.length;"
               "document.body.dataset.imagesLoaded=i.filter(x=>x.complete&&x.naturalWidth>0).length;"
               "});</script></body></html>")
    with open(os.path.join(folder, "report.html"), "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    parser = argparse.ArgumentParser(description="Plots and an HTML report of a penumbra study")
    parser.add_argument("folder")
    parser.add_argument("--budget-ms", type=float, help="default: the study's")
    args = parser.parse_args()
    rows, doc = load(args.folder)
    budget = args.budget_ms if args.budget_ms else float(doc.get("budgetMs", 33.3))
    points = summaries(rows)
    plot_error_vs_time(points, budget, os.path.join(args.folder, "error_vs_time.png"))
    plot_error_vs_spp(points, os.path.join(args.folder, "error_vs_spp.png"))
    write_html(args.folder, rows, doc, points, budget)
    print(f"wrote {os.path.join(args.folder, 'report.html')}")


if __name__ == "__main__":
    main()
