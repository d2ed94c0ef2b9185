#!/usr/bin/env python3
"""Writes resources/scenarios/ais-harbour.json: the busy harbour (40 radar targets) with AIS
transponders on 30 of them (20 class A, 10 class B), antenna places drawn per ship. Deterministic
(seeded), so the file is reproducible: python3 scripts/make_ais_harbour.py."""
import json
import pathlib
import random

root = pathlib.Path(__file__).resolve().parent.parent
src = json.loads((root / "resources/scenarios/busy-harbour.json").read_text())
rng = random.Random(20)
s = dict(src)
s["name"] = "AIS harbour: 40 radar targets, 30 with AIS (20 class A, 10 class B)"
s["description"] = ("The busy harbour (own ship at 6 kn among 40 vessels, radar every 2 s, Pd 0.9, sea "
                    "clutter) with AIS transponders on 30 of the vessels: 20 class A (reports every 10 s, "
                    "3 1/3 s turning; type 5 dimensions) and 10 class B (every 30 s; type 24), antennas off "
                    "the hull's centre, GNSS errors correlated in time, 0.2-3 s latency, 5% of messages lost. "
                    "Ten vessels carry no AIS. The association and fusion reference (docs/fusion.md).")
targets = []
ids = list(range(len(src["targets"])))
with_ais = sorted(rng.sample(ids, 30))
class_a = set(rng.sample(with_ais, 20))
for i, t in enumerate(src["targets"]):
    t = dict(t)
    if i in with_ais:
        if i in class_a:
            length = rng.randint(40, 250)
            beam = max(8, int(length * rng.uniform(0.12, 0.17)))
            to_bow = int(length * rng.uniform(0.55, 0.9))
            to_port = int(beam * rng.uniform(0.3, 0.7))
            t["ais"] = {"class": "A", "mmsi": 366000000 + 100 * t["id"],
                        "antenna_m": [to_bow, length - to_bow, to_port, beam - to_port]}
        else:
            length = rng.randint(8, 24)
            beam = max(3, int(length * 0.3))
            to_bow = int(length * rng.uniform(0.3, 0.7))
            to_port = int(beam * 0.5)
            t["ais"] = {"class": "B", "mmsi": 338000000 + 100 * t["id"],
                        "antenna_m": [to_bow, length - to_bow, to_port, beam - to_port]}
    targets.append(t)
s["targets"] = targets
(root / "resources/scenarios/ais-harbour.json").write_text(json.dumps(s, indent=1) + "\n")
