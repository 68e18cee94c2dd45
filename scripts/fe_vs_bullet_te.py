#!/usr/bin/env python3
"""Loaded TE of a slow Bullet run (gearsim run paper_te_loaded.yaml) against the FE sweep
(gearsim fe-te) over the same mesh period: the FE positions are placed on the Bullet record by
the interval where planet 0's sun mesh carries no force (the faulty tooth's single-pair zone) when
both show one, else by the healthy window. Prints peak-to-peak TE in µrad.

Usage: fe_vs_bullet_te.py BULLET_DIR FE_DIR [--window T0 T1] [--mesh-period S]
  --window: Bullet time window (s) for a healthy comparison, default 0.3 1.2
  --mesh-period: mesh period of the Bullet run in s, default from paper_te_loaded (36.36 ms)
"""
import csv
import math
import sys


def column(rows, key):
    return [float(r[key]) for r in rows]


def zero_interval_centre(xs, fs, limit_N=1.0):
    zs = [x for x, f in zip(xs, fs) if f < limit_N]
    return (min(zs) + max(zs)) / 2 if zs else None


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    bullet, fe = argv[1], argv[2]
    window = (0.3, 1.2)
    period = 2 * math.pi / (24 * (9.0 - 9.0 / 5))  # z_s (ω_s − ω_c), paper_te_loaded
    if '--window' in argv:
        i = argv.index('--window')
        window = (float(argv[i + 1]), float(argv[i + 2]))
    if '--mesh-period' in argv:
        period = float(argv[argv.index('--mesh-period') + 1])
    state = list(csv.DictReader(open(bullet + '/state.csv')))
    contacts = list(csv.DictReader(open(bullet + '/contacts.csv')))
    t = column(state, 'time_s')
    te = column(state, 'te_rad')
    tc = column(contacts, 'time_s')
    f0 = column(contacts, 'sun__planet_0_force_N')
    fe_te = list(csv.DictReader(open(fe + '/te_loaded.csv')))
    fe_ms = list(csv.DictReader(open(fe + '/mesh_stiffness.csv')))
    phase = column(fe_te, 'mesh_phase')
    te_fe = column(fe_te, 'te_loaded_rad')
    fe_f0 = column(fe_ms, 'sun_planet_0_force_N')

    def interp(x):
        lo, hi = 0, len(t) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if t[mid] <= x:
                lo = mid
            else:
                hi = mid
        w = (x - t[lo]) / (t[hi] - t[lo])
        return te[lo] * (1 - w) + te[hi] * w

    p2p = lambda v: (max(v) - min(v)) * 1e6
    print(f"FE: {len(phase)} positions, loaded TE p2p {p2p(te_fe):.2f} µrad "
          f"(mean {sum(te_fe) / len(te_fe) * 1e6:.1f} µrad)")
    fe_centre = zero_interval_centre(phase, fe_f0)
    late = [(x, f) for x, f in zip(tc, f0) if x > window[1]]
    b_centre = zero_interval_centre([x for x, _ in late], [f for _, f in late]) if late else None
    if fe_centre is not None and b_centre is not None:
        start = b_centre - fe_centre * period
        print(f"fault: FE planet 0 unloaded around phase {fe_centre:.4f}; Bullet around t = {b_centre:.5f} s")
        samples = [interp(start + ph * period) for ph in phase]
        span = [v for x, v in zip(t, te) if start <= x <= start + period]
        print(f"Bullet at the FE's phases: p2p {p2p(samples):.2f} µrad; over the whole period "
              f"[{start:.5f}, {start + period:.5f}] s: p2p {p2p(span):.2f} µrad "
              f"(mean {sum(span) / len(span) * 1e6:.1f} µrad)")
        for ph, a, b in zip(phase, te_fe, samples):
            print(f"  phase {ph:.4f}: FE {a * 1e6:9.2f}  Bullet {b * 1e6:9.2f} µrad")
    else:
        # Place the FE phases on the Bullet record by planet 0's sun-mesh pair count: the offsets
        # (in 1/200 of a period) at which Bullet's count differs from the FE's own count (teeth
        # carrying > 2 % of the mesh force, tooth_forces.csv) at the fewest FE phases; the centre
        # of the longest run of such offsets.
        counts = {}
        for r in csv.DictReader(open(fe + '/tooth_forces.csv')):
            if r['planet'] == '0':
                counts.setdefault(int(r['position']), []).append(float(r['force_N']))
        n_fe = [sum(1 for f in counts[i] if f > 0.02 * sum(counts[i])) for i in sorted(counts)]
        pairs = column(contacts, 'sun__planet_0_tooth_pairs')
        t0 = window[0]

        def pairs_at(x):
            i = min(range(len(tc)), key=lambda j: abs(tc[j] - x)) if len(tc) < 50 else \
                max(0, min(len(tc) - 1, round((x - tc[0]) / (tc[1] - tc[0]))))
            return pairs[i]
        miss = [sum(1 for ph, n in zip(phase, n_fe) if pairs_at(t0 + (k / 200 + ph) * period) != n)
                for k in range(200)]
        good = [k for k in range(200) if miss[k] == min(miss)]
        print(f"fewest FE phases whose pair count Bullet does not share: {min(miss)} of {len(phase)}")
        print(f"FE pair counts of planet 0's sun mesh at its phases: {n_fe}")
        if good:
            runs, cur = [], [good[0]]
            for k in good[1:]:
                if k == cur[-1] + 1:
                    cur.append(k)
                else:
                    runs.append(cur)
                    cur = [k]
            runs.append(cur)
            best = max(runs, key=len)
            off = (best[0] + best[-1]) / 2 / 200
            n = int((window[1] - window[0]) / period) - 1
            sampled = []
            for k in range(n):
                v = [interp(t0 + (k + off + ph) * period) for ph in phase]
                sampled.append(p2p(v))
            print(f"Bullet at the FE's phases (offset {off:.3f} of a period; pair counts agree over "
                  f"{len(best) / 200:.3f} of a period): p2p {min(sampled):.2f}…{max(sampled):.2f}, "
                  f"mean {sum(sampled) / len(sampled):.2f} µrad over {n} periods")
        else:
            print("no offset makes Bullet's pair counts equal the FE's at every FE phase")
        span = [v for x, v in zip(t, te) if window[0] <= x <= window[1]]
        n = int((window[1] - window[0]) / period)
        per = []
        for k in range(n):
            a = window[0] + k * period
            seg = [v for x, v in zip(t, te) if a <= x <= a + period]
            if seg:
                per.append(p2p(seg))
        print(f"Bullet healthy window {window[0]}–{window[1]} s: p2p {p2p(span):.2f} µrad "
              f"(mean {sum(span) / len(span) * 1e6:.1f} µrad); per mesh period p2p "
              f"{min(per):.2f}…{max(per):.2f}, mean {sum(per) / len(per):.2f} µrad over {len(per)} periods")
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
