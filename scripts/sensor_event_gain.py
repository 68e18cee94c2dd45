#!/usr/bin/env python3
"""The in-phase events of a paper run's housing sensor normalised by each planet's geometric gain.

For each run folder FOLDER0, FOLDER1, FOLDER2 (the 43 µm fault on planet 0, 1, 2: `gearsim run
assets/scenarios/paper_dynamics.yaml --out FOLDERk --set render=null --set
'planetary.faulty_planets={k: planet_faulty}'`), the fault events are the instants the faulty
planet's sun-mesh force (steps.h5, full rate) falls below 20 N after 0.1 s (one per planet turn);
each planet's geometric gain G = Σw²/Σw of its Hann window weight at those instants (sensor at
90°, 120° wide: the paper scenario's `housing_top`), and the event size a of analysis.json's
in-phase localisation divided by it (docs/condition-monitoring.md).

    /usr/bin/python3 scripts/sensor_event_gain.py FOLDER_PREFIX [dt DT]   (FOLDER_PREFIX0/1/2)

Needs numpy and h5py.
"""
import h5py, numpy as np, json, sys, csv
def run(d, k):
    f = h5py.File(d + "/steps.h5", "r"); c = f["contacts"]
    step, pair, imp = c["step"][:], c["pair"][:], c["normal_impulse_N_s"][:]
    dt = DT
    n = int(f["state"].shape[0]); F = np.zeros(n + 1); m = pair == k
    np.add.at(F, step[m], imp[m] / dt)
    t = np.arange(n + 1) * dt
    low = F < 20; ev = np.flatnonzero(low[1:] & ~low[:-1]) + 1
    ev = ev[t[ev] > 0.1]
    # merge events closer than 5 ms
    evs = []
    for e in ev:
        if not evs or t[e] - t[evs[-1]] > 5e-3: evs.append(e)
    te = t[evs]
    st = np.genfromtxt(d + "/state.csv", delimiter=",", names=True)
    car = np.interp(te, st["time_s"], st["carrier_angle_rad"])
    a = json.load(open(d + "/analysis.json"))["sensors"][0]
    out = []
    for grid in ["in_phase", "in_phase_refined_grid"]:
        ip = a[grid]
        row = []
        for i, p in enumerate(ip["planets"]):
            pos = car + 2 * np.pi * i / 3
            delta = np.angle(np.exp(1j * (pos - np.pi / 2)))
            W = np.radians(120)
            w = np.where(np.abs(delta) < W / 2, 0.5 * (1 + np.cos(2 * np.pi * delta / W)), 0)
            G = (w ** 2).sum() / w.sum() if w.sum() > 0 else float('nan')
            row.append((p["event_rms_m_s2"], G, p["event_rms_m_s2"] / G if G > 0 else float('nan')))
        out.append(grid + ": " + "  ".join("a=%.1f G=%.2f n=%.1f" % r for r in row) + "  argmax n = %d" % int(np.nanargmax([r[2] for r in row])))
    return len(te), out
if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != "dt"):
    sys.exit("usage: sensor_event_gain.py FOLDER_PREFIX [dt DT]")
DT = float(sys.argv[3]) if len(sys.argv) == 4 else 2e-5
for k in range(3):
    ne, out = run(sys.argv[1] + "%d" % k, k)
    print("fault on planet", k, "events", ne); print("  " + "\n  ".join(out))
