#!/usr/bin/python3
"""Summarise the raw P1 runs written by bench/p1_cube.sh.

For every (n, EAS count) the best (minimum; --statistic median for the median) over the
successful repeats of each column is taken, column by column (the median total is kept too). Derived columns:
  assembly_per_call_s = assembly_seconds / assemblies  (one assembly: element loop + scatter
                        + loads; a linear run makes 2: before and after the correction)
  elements_per_second = n^3 / assembly_per_call_s
Growth exponents p of time ~ N_eq^p are log-log slopes between successive sizes,
p = ln(t2/t1) / ln(N2/N1), and a least-squares slope over all sizes; N_eq is frix's
`equations` stat (3 x nodes, the fixed base DOFs included).
Targets (benchmarks.md P1 / the issue): HEX8 assembly >= 1e5 elements/s on one core;
n = 30 assembled and solved in < 30 s; n = 40 within 4 GB peak memory.
"""
import argparse
import csv
import math
import os
import statistics
import sys

PHASES = [
    ("assembly_per_call_s", "assembly (per call)"),
    ("analyse_seconds", "ordering + symbolic"),
    ("factorize_seconds", "factorization"),
    ("solve_seconds", "solve"),
    ("total_seconds", "total"),
    ("peak_memory_mb", "peak memory"),
]
NUMERIC = [
    "equations", "matrix_nonzeros", "factor_nonzeros", "newton_iterations", "assemblies",
    "factorizations", "assembly_seconds", "analyse_seconds", "factorize_seconds",
    "solve_seconds", "total_seconds", "peak_memory_mb", "max_rss_mb", "wall_seconds",
]
ASSEMBLY_TARGET = 1.0e5      # HEX8 elements per second, one core
TOTAL_TARGET_N30 = 30.0      # seconds
MEMORY_TARGET_N40 = 4096.0   # MiB (4 GB read as 4 GiB; 4000 MB changes nothing below)


def read_raw(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def summarise(rows, pick):
    """pick: min (best of the repeats: the machine is shared, contention only adds time) or
    statistics.median, applied column by column."""
    groups = {}
    for row in rows:
        groups.setdefault((int(row["n"]), int(row["eas"])), []).append(row)
    summary = []
    for (n, eas), runs in sorted(groups.items()):
        good = [r for r in runs if r["status"] == "ok"]
        entry = {"n": n, "eas": eas, "elements": n ** 3, "runs": len(runs), "ok_runs": len(good),
                 "status": "ok" if good else ";".join(sorted({r["status"] for r in runs})),
                 "openblas_threads": runs[0]["openblas_threads"]}
        if good:
            for key in NUMERIC:
                entry[key] = pick(float(r[key]) for r in good)
            if "load1" in good[0]:
                entry["load1"] = max(float(r["load1"]) for r in good)
            entry["median_total_seconds"] = statistics.median(float(r["total_seconds"]) for r in good)
            per_call = [float(r["assembly_seconds"]) / float(r["assemblies"]) for r in good]
            entry["assembly_per_call_s"] = pick(per_call)
            entry["elements_per_second"] = n ** 3 / entry["assembly_per_call_s"]
            entry["other_seconds"] = pick(
                float(r["total_seconds"]) - sum(float(r[k]) for k in (
                    "assembly_seconds", "analyse_seconds", "factorize_seconds", "solve_seconds"))
                for r in good)
        else:
            rss = [float(r["max_rss_mb"]) for r in runs if r["max_rss_mb"]]
            entry["max_rss_mb"] = max(rss) if rss else float("nan")
        summary.append(entry)
    return summary


def slope(x1, y1, x2, y2):
    if min(x1, y1, x2, y2) <= 0.0:
        return float("nan")
    return math.log(y2 / y1) / math.log(x2 / x1)


def least_squares_slope(xs, ys):
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def exponents(summary):
    """{eas: [(n1, n2, {phase: p})], ...} and {eas: {phase: least-squares p}}."""
    pairs, overall = {}, {}
    for eas in sorted({e["eas"] for e in summary}):
        ok = [e for e in summary if e["eas"] == eas and e["status"] == "ok"]
        ok.sort(key=lambda e: e["n"])
        pairs[eas] = []
        for a, b in zip(ok, ok[1:]):
            pairs[eas].append((a["n"], b["n"], {key: slope(a["equations"], a[key],
                                                           b["equations"], b[key])
                                                for key, _ in PHASES}))
        overall[eas] = {key: least_squares_slope([e["equations"] for e in ok],
                                                 [e[key] for e in ok]) for key, _ in PHASES}
    return pairs, overall


def variant_name(eas):
    return "HEX8" if eas == 0 else f"HEX8-EAS{eas}"


def fmt(value, digits=3):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, float):
        if value == 0.0:
            return "0"
        if abs(value) >= 1000:
            return f"{value:,.0f}".replace(",", " ")
        return f"{value:.{digits}g}"
    return str(value)


def targets(summary, cpu_rows):
    lines = []
    cpu_hex8 = [r for r in cpu_rows if int(r["eas"]) == 0]
    if cpu_hex8:
        rates = [(int(r["n"]), float(r["elements_per_cpu_second"])) for r in cpu_hex8]
        worst = min(v for _, v in rates)
        lines.append(f"- HEX8 assembly >= 100 000 elements/s on one core, in CPU time "
                     f"(p1_assembly_timer): {'MET' if worst >= ASSEMBLY_TARGET else 'MISSED'} - "
                     f"{fmt(worst)} to {fmt(max(v for _, v in rates))} elements per CPU second "
                     f"over n = {', '.join(str(n) for n, _ in rates)}.")
    hex8 = [e for e in summary if e["eas"] == 0 and e["status"] == "ok"]
    if hex8:
        rates = [(e["n"], e["elements_per_second"]) for e in hex8]
        worst = min(r for _, r in rates)
        best = max(r for _, r in rates)
        met = worst >= ASSEMBLY_TARGET
        lines.append(f"- HEX8 assembly >= 100 000 elements/s, in wall time of the frix runs: "
                     f"{'MET' if met else 'MISSED'} - measured {fmt(worst)} to {fmt(best)} "
                     f"elements/s over n = {', '.join(str(n) for n, _ in rates)}.")
    for eas in sorted({e["eas"] for e in summary}):
        row = next((e for e in summary if e["eas"] == eas and e["n"] == 30), None)
        if row is None:
            continue
        if row["status"] != "ok":
            lines.append(f"- n = 30 {variant_name(eas)} in < 30 s: MISSED - run failed "
                         f"({row['status']}).")
            continue
        met = row["total_seconds"] < TOTAL_TARGET_N30
        lines.append(f"- n = 30 {variant_name(eas)} ({fmt(row['equations'])} equations) "
                     f"assembled and solved in < 30 s: {'MET' if met else 'MISSED'} - "
                     f"total {fmt(row['total_seconds'])} s (best; median of the repeats "
                     f"{fmt(row['median_total_seconds'])} s; wall incl. start-up "
                     f"{fmt(row['wall_seconds'])} s).")
    for eas in sorted({e["eas"] for e in summary}):
        row = next((e for e in summary if e["eas"] == eas and e["n"] == 40), None)
        if row is None:
            continue
        if row["status"] != "ok":
            lines.append(f"- n = 40 {variant_name(eas)} within 4 GB: run failed ({row['status']}), "
                         f"max RSS {fmt(row['max_rss_mb'])} MiB.")
            continue
        peak = max(row["peak_memory_mb"], row["max_rss_mb"])
        met = peak <= MEMORY_TARGET_N40
        lines.append(f"- n = 40 {variant_name(eas)} within 4 GB peak memory: "
                     f"{'MET' if met else 'MISSED'} - peak {fmt(peak)} MiB.")
    return lines


def write_summary_csv(path, summary):
    keys = ["n", "eas", "elements", "runs", "ok_runs", "status", "openblas_threads"] + NUMERIC + [
        "median_total_seconds", "assembly_per_call_s", "elements_per_second", "other_seconds", "load1"]
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=keys, extrasaction="ignore")
        writer.writeheader()
        for entry in summary:
            writer.writerow({k: entry.get(k, "") for k in keys})


def markdown(summary, pairs, overall, machine_lines, label, cpu_rows):
    out = ["# P1 results: linear elastic cube n x n x n (bench/p1_cube.sh)", ""]
    out += ["Machine and run conditions:", ""]
    out += [f"- {line}" for line in machine_lines]
    out += ["", f"{label} over the successful repeats, column by column; times are wall-clock seconds from frix's "
            "`stat` lines; `asm/call` = assembly_seconds / assemblies; elements/s = n^3 / asm/call; "
            "`other` = total - (all assemblies + analyse + factorize + solve): deck reading, mesh "
            "generation, sparsity pattern, Dirichlet rows, output; "
            "max RSS from `/usr/bin/time -v`; max load = the highest 1-minute load average seen "
            "when a repeat started (2 cores: above 2, the runs shared the cores).", ""]
    header = ("| variant | n | equations | K nonzeros | L nonzeros | runs ok | asm/call s | "
              "elements/s | analyse s | factorize s | solve s | other s | total s (median) | peak MiB | "
              "max RSS MiB | max load |")
    out += [header, "|" + "---|" * (header.count("|") - 1)]
    for e in summary:
        if e["status"] != "ok":
            out.append(f"| {variant_name(e['eas'])} | {e['n']} | - | - | - | 0/{e['runs']} "
                       f"({e['status']}) | - | - | - | - | - | - | - | - | {fmt(e['max_rss_mb'])} | - |")
            continue
        out.append(
            f"| {variant_name(e['eas'])} | {e['n']} | {fmt(e['equations'])} | "
            f"{fmt(e['matrix_nonzeros'])} | {fmt(e['factor_nonzeros'])} | {e['ok_runs']}/{e['runs']} | "
            f"{fmt(e['assembly_per_call_s'])} | {fmt(e['elements_per_second'])} | "
            f"{fmt(e['analyse_seconds'])} | {fmt(e['factorize_seconds'])} | "
            f"{fmt(e['solve_seconds'])} | {fmt(e['other_seconds'])} | {fmt(e['total_seconds'])} ({fmt(e['median_total_seconds'])}) | "
            f"{fmt(e['peak_memory_mb'])} | {fmt(e['max_rss_mb'])} | {fmt(e.get('load1'))} |")
    out += ["", "Growth exponents p in time ~ N_eq^p (log-log slope between successive sizes; "
            "last row: least-squares slope over all sizes):", ""]
    head = "| variant | sizes | " + " | ".join(label for _, label in PHASES) + " |"
    out += [head, "|" + "---|" * (head.count("|") - 1)]
    for eas, rows in pairs.items():
        for n1, n2, p in rows:
            out.append(f"| {variant_name(eas)} | {n1} -> {n2} | " +
                       " | ".join(f"{p[k]:.2f}" for k, _ in PHASES) + " |")
        if len(rows) > 1:
            out.append(f"| {variant_name(eas)} | all (fit) | " +
                       " | ".join(f"{overall[eas][k]:.2f}" for k, _ in PHASES) + " |")
    if cpu_rows:
        out += ["", "Assembly in CPU seconds of the frix process (bench/p1_assembly_timer, best of 5 "
                "assemblies of fint + tangent after a warm-up; kernel = element evaluate alone, "
                "scatter = the rest: gather, scatter into K and fint, zeroing):", ""]
        head = ("| variant | n | CPU s / assembly | wall s / assembly | elements per CPU s | "
                "kernel CPU s | scatter + rest CPU s | load (1 min) |")
        out += [head, "|" + "---|" * (head.count("|") - 1)]
        for r in cpu_rows:
            out.append(f"| {variant_name(int(r['eas']))} | {r['n']} | "
                       f"{fmt(float(r['assembly_cpu_seconds']))} | "
                       f"{fmt(float(r['assembly_wall_seconds']))} | "
                       f"{fmt(float(r['elements_per_cpu_second']))} | "
                       f"{fmt(float(r['kernel_cpu_seconds']))} | "
                       f"{fmt(float(r['scatter_and_rest_cpu_seconds']))} | {r['load1']} |")
    out += ["", "Targets:", ""] + targets(summary, cpu_rows) + [""]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--raw", required=True)
    parser.add_argument("--machine", required=True)
    parser.add_argument("--summary", required=True)
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--assembly-cpu", default=None,
                        help="CSV of p1_assembly_timer runs (CPU-second assembly timings)")
    parser.add_argument("--statistic", choices=["best", "median"], default="best")
    args = parser.parse_args()
    pick = min if args.statistic == "best" else statistics.median
    label = "Best (minimum)" if args.statistic == "best" else "Medians"
    summary = summarise(read_raw(args.raw), pick)
    if not summary:
        sys.exit("p1_report.py: no runs in " + args.raw)
    pairs, overall = exponents(summary)
    with open(args.machine) as handle:
        machine_lines = [line.rstrip("\n") for line in handle if line.strip()]
    write_summary_csv(args.summary, summary)
    cpu_rows = []
    if args.assembly_cpu and os.path.isfile(args.assembly_cpu):
        cpu_rows = read_raw(args.assembly_cpu)
    text = markdown(summary, pairs, overall, machine_lines, label, cpu_rows)
    with open(args.markdown, "w") as handle:
        handle.write(text)
    print(text)


if __name__ == "__main__":
    main()
