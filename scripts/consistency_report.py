#!/usr/bin/env python3
"""Runs the DRKF Monte Carlo studies and prints the tables of docs/consistency.md (Markdown).

usage: scripts/consistency_report.py [--cli build/ci/app/reckoner-cli] [--runs 50] [--out out/consistency]
Needs only the Python standard library and a built reckoner-cli.
"""
import argparse
import json
import os
import subprocess

SCENARIOS = ["matched-model", "table1-test1", "table1-test2", "table1-test3", "table1-test4", "table1-test5", "default"]


def study(cli, name, runs, out):
    d = os.path.join(out, name)
    subprocess.run([cli, "montecarlo", f"builtin:{name}", "--runs", str(runs), "--threads", "2", "--out", d,
                    "--quiet"], check=True)
    with open(os.path.join(d, "summary.json")) as f:
        return json.load(f)


def sd_at(s, t):
    per = s["per_time"]
    for ts, sd in zip(per["t_s"], per["rms_sd_position_m"]):
        if ts >= t - 1e-9:
            return sd
    return float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default="build/ci/app/reckoner-cli")
    ap.add_argument("--runs", type=int, default=50)
    ap.add_argument("--out", default="out/consistency")
    a = ap.parse_args()
    results = {n: study(a.cli, n, a.runs, a.out) for n in SCENARIOS}
    lo, hi = results["matched-model"]["nees_bounds"]
    print(f"{a.runs} runs per scenario; 95% bounds of the mean NEES (11 states): [{lo:.2f}, {hi:.2f}]\n")
    print("| scenario | phase | sensors | mean NEES | max over time | inside | pos RMSE (m) | vel RMSE (m/s) | error within 3 sd |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n, s in results.items():
        for p in s["phases"]:
            verdict = "yes" if p["inside"] else ("low" if p["mean_nees"] < lo else "HIGH")
            print(f"| {n} | {p['index'] + 1} ({p['start_s']:.0f}-{p['end_s']:.0f} s) | {p['label']} | "
                  f"{p['mean_nees']:.2f} | {p['max_mean_nees']:.2f} | {verdict} | {p['rmse_position_m']:.1f} | "
                  f"{p['rmse_velocity_mps']:.3f} | {100 * p['fraction_within_3sd']:.1f}% |")
    print("\n| scenario | steady sd before outage (m) | sd at end of dead reckoning (m) | sd 30 s after GPS returns (m) |")
    print("|---|---|---|---|")
    for n, s in results.items():
        phases = s["phases"]
        first = phases[0]
        per = s["per_time"]
        steady = [sd for t, sd in zip(per["t_s"], per["rms_sd_position_m"]) if first["end_s"] - 60 <= t < first["end_s"]]
        steady = sum(steady) / len(steady)
        back = next(p for i, p in enumerate(phases) if i > 0 and p["kind"] == "gps" and phases[i - 1]["kind"] != "gps")
        before = phases[back["index"] - 1]["sd_position_end_m"]
        print(f"| {n} | {steady:.1f} | {before:.1f} | {sd_at(s, back['start_s'] + 30):.1f} |")


if __name__ == "__main__":
    main()
