#!/usr/bin/env python3
"""Fits the stored device cost profiles (samples/cost/lavapipe.json from the calibration sweep,
samples/cost/h200.json from the stored H200 rows with counts measured here) and writes how well
each predicts frames it was and was not fitted on into docs/cost.md ("How well the stored
profiles predict"). Every command it runs is printed in the section.

    python3 scripts/cost_report.py [--shadowc build/cli/shadowc] [--out build]

The sweeps cache their rows in --out (build/cost-sweep, build/h200-counts-*): a rerun measures only
what changed. Calibrate on a quiet machine: the lavapipe rows are timed."""
import argparse
import json
import math
import os
import re
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generated_section import write_section  # noqa: E402

LINE = re.compile(r"^(.*?): (\d+) frames, median \|ln\(predicted/measured\)\| ([\d.]+) \(([\d.]+)x\), largest ([\d.]+)x, "
                  r"(\d+) of (\d+) \(([\d.]+) %\) within 1.5x")


def run(cmd, commands):
    commands.append(shlex.join(cmd))
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    sys.stdout.write(out)
    return out


def qualities(out):
    rows = []
    lines = out.splitlines()
    for i, line in enumerate(lines):
        m = LINE.match(line)
        if m:
            worst = lines[i + 1].strip().removeprefix("worst: ") if i + 1 < len(lines) else ""
            rows.append((m.group(1), int(m.group(2)), float(m.group(4)), float(m.group(5)), int(m.group(6)), worst))
    return rows


def rows_of(path):
    with open(path) as f:
        return json.load(f)["rows"]


def shade(row):
    return sum(p["median_ms"] for p in row["passes"] if p["kind"] == "shade")


def same_counts(cal, lss_counts):
    """Where the time goes beyond the fetch count: footprint on a GPU, code shape on lavapipe."""
    out = ["Where the time goes beyond the fetch count, from the same rows:", "",
           "| device | variant | case | depth fetches / receiver | depth block switches / receiver "
           "| SAT fetches / receiver | shade ms |",
           "|---|---|---|---|---|---|---|"]
    counted = {(r["variant"], r["case"]): r for r in rows_of(os.path.join(lss_counts, "results.json"))}
    for r in rows_of("bench/results/h200_light_size_study.json"):
        if r["variant"] == "pcss[search=16,taps=16]" and r["case"].endswith("map 1024"):
            w = counted[(r["variant"], r["case"])]["work"]["per_receiver"]
            out.append(f"| NVIDIA H200 | {r['variant']} | {r['case']} | {w.get('depth_fetches', 0):.1f} | "
                       f"{w.get('depth_block_switches', 0):.1f} | {w.get('sat_fetches', 0):.1f} | {shade(r):.4f} |")
    for r in rows_of(os.path.join(cal, "results.json")):
        if r["variant"] in ("vssm_quadtree_table", "vssm_quadtree_unrolled") and r["case"].startswith("two_planes"):
            w = r["work"]["per_receiver"]
            out.append(f"| lavapipe | {r['variant']} | {r['case']} | {w.get('depth_fetches', 0):.1f} | "
                       f"{w.get('depth_block_switches', 0):.1f} | {w.get('sat_fetches', 0):.1f} | {shade(r):.2f} |")
    out.append("")
    return out


def agreement(first, second):
    """Two runs' measured frames of the same rows, as a profile's predictions are judged:
    (count, median ratio, largest ratio, within 1.5x, worst)."""
    a = {(r["variant"], r["case"]): r["total_ms"] for r in rows_of(os.path.join(first, "results.json"))}
    pairs = [(abs(math.log(a[k] / r["total_ms"])), k, a[k], r["total_ms"])
             for r in rows_of(os.path.join(second, "results.json"))
             for k in [(r["variant"], r["case"])] if k in a and a[k] > 0 and r["total_ms"] > 0]
    logs = sorted(p[0] for p in pairs)
    n = len(logs)
    median = logs[n // 2] if n % 2 else 0.5 * (logs[n // 2 - 1] + logs[n // 2])
    worst = max(pairs)
    return (n, math.exp(median), math.exp(logs[-1]), sum(x <= math.log(1.5) for x in logs),
            f"{worst[1][0]} on {worst[1][1]}: first run {worst[2]:.3f} ms, rerun {worst[3]:.3f} ms")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shadowc", default="build/cli/shadowc")
    ap.add_argument("--out", default="build")
    a = ap.parse_args()
    sc, o = a.shadowc, a.out
    commands, table = [], []
    cal = os.path.join(o, "cost-sweep")
    run([sc, "sweep", "samples/sweeps/cost_calibration.json", "-o", cal, "-j", "1", "--progress", "lines"], [])
    commands.append(f"{sc} sweep samples/sweeps/cost_calibration.json -o {cal} -j 1")

    def add(profile, what, out, only=None):
        for label, n, median, largest, within, worst in qualities(out):
            how = label if label in ("fitted on", "held out") else "checked on"
            if only is None or how == only:
                table.append((profile, what, how, n, median, largest, within, worst))

    add("lavapipe", "calibration sweep",
        run([sc, "cost-profile", cal, "--device", "lavapipe", "-o", "samples/cost/lavapipe.json"], commands))
    # The floor a lavapipe profile is judged against: the same sweep timed again right after,
    # its readings against the first run's, and the profile fitted on the first run checked on it.
    rerun = os.path.join(o, "cost-sweep-rerun")
    run([sc, "sweep", "samples/sweeps/cost_calibration.json", "-o", rerun, "-j", "1", "--progress", "lines"], [])
    commands.append(f"{sc} sweep samples/sweeps/cost_calibration.json -o {rerun} -j 1")
    table.append(("lavapipe", "the rerun's measured frames", "against the first run's") + agreement(cal, rerun))
    add("lavapipe", "the rerun (same rows, timed again right after)",
        run([sc, "cost-profile", rerun, "--profile", "samples/cost/lavapipe.json"], commands))
    for scene in ["two_planes", "large_penumbra", "duck"]:
        out = run([sc, "cost-profile", cal, "--hold-out", scene, "-o", os.path.join(o, f"cost-holdout-{scene}.json")],
                  commands)
        add("lavapipe", f"calibration sweep, {scene} (fitted on the other two)", out, only="held out")
    counts = {}
    for name in ["light_size_study", "mixed_vs_h3"]:
        d = os.path.join(o, "h200-counts-" + ("lss" if name == "light_size_study" else "mix"))
        run([sc, "sweep", f"bench/sweeps/{name}.json", "--counters", "-o", d, "-j", "1", "--progress", "lines"], [])
        commands.append(f"{sc} sweep bench/sweeps/{name}.json --counters -o {d} -j 1")
        counts[name] = d
    add("NVIDIA H200", "bench/results/h200_light_size_study.json",
        run([sc, "cost-profile", "bench/results/h200_light_size_study.json", "--counts-from", counts["light_size_study"],
             "--device", "NVIDIA H200", "-o", "samples/cost/h200.json"], commands))
    add("NVIDIA H200", "bench/results/h200_mixed_vs_h3.json",
        run([sc, "cost-profile", "bench/results/h200_mixed_vs_h3.json", "--counts-from", counts["mixed_vs_h3"],
             "--profile", "samples/cost/h200.json"], commands))

    body = ["Generated by `python3 scripts/cost_report.py`, which ran:", "", "```"] + commands + ["```", ""]
    body += ["| profile | frames | how | count | median ratio | largest ratio | within 1.5x | worst |",
             "|---|---|---|---|---|---|---|---|"]
    for profile, what, how, n, median, largest, within, worst in table:
        body.append(f"| {profile} | {what} | {how} | {n} | {median:.2f}x | {largest:.2f}x | "
                    f"{within} ({100.0 * within / n:.0f} %) | {worst} |")
    body.append("")
    body.append("A ratio is max(predicted, measured) / min(predicted, measured) of a whole frame (every pass summed).")
    body.append("")
    body += same_counts(cal, counts["light_size_study"])
    write_section("docs/cost.md", "cost_report.py", "cost", "\n".join(body) + "\n")


if __name__ == "__main__":
    main()
