#!/usr/bin/env python3
"""Nominal tooth-root stress sigma_F0 = F_t/(b m) Y_F Y_S of ISO 6336-3:2019 method B (external
spur gear, x = 0, no protuberance, load at the outer point of single-pair contact), the reference
for gearsim fe-te's root stresses (docs/fe.md).

Usage: iso6336_root_stress.py Z Z_MATE F_T_N [m_mm=1] [b_mm=10] [alpha_deg=20] [h_fP=1.25]
       [rho_fP=0.38] [h_a=1]
"""
import sys
from math import acos, cos, pi, radians, sin, sqrt, tan


def sigma_f0(z, z2, Ft, m=1.0, b=10.0, alpha_deg=20.0, hfP=1.25, rhofP=0.38, ha=1.0):
    a = radians(alpha_deg)
    E = pi * m / 4 - hfP * m * tan(a) - (1 - sin(a)) * rhofP * m / cos(a)
    G = rhofP - hfP
    H = 2 / z * (pi / 2 - E / m) - pi / 3
    th = pi / 6
    for _ in range(200):
        th = 2 * G / z * tan(th) - H
    sFn = z * sin(pi / 3 - th) + sqrt(3) * (G / cos(th) - rhofP)       # / m
    rhoF = rhofP + 2 * G * G / (cos(th) * (z * cos(th) ** 2 - 2 * G))  # / m
    d, d2 = m * z, m * z2
    db, db2 = d * cos(a), d2 * cos(a)
    da, da2 = d + 2 * ha * m, d2 + 2 * ha * m
    eps = (sqrt((da / 2) ** 2 - (db / 2) ** 2) + sqrt((da2 / 2) ** 2 - (db2 / 2) ** 2)
           - (d + d2) / 2 * sin(a)) / (pi * m * cos(a))
    den = 2 * sqrt((sqrt((da / 2) ** 2 - (db / 2) ** 2) - pi * d * cos(a) / z * (eps - 1)) ** 2 + (db / 2) ** 2)
    aen = acos(db / den)
    inv = lambda x: tan(x) - x
    ge = 0.5 * pi / z + inv(a) - inv(aen)
    aFen = aen - ge
    hFe = 0.5 * ((cos(ge) - sin(ge) * tan(aFen)) * den / m - z * cos(pi / 3 - th) - G / cos(th) + rhofP)
    YF = 6 * hFe * cos(aFen) / (sFn ** 2 * cos(a))
    L = sFn / hFe
    qs = sFn / (2 * rhoF)
    YS = (1.2 + 0.13 * L) * qs ** (1 / (1.21 + 2.3 / L))
    return dict(contact_ratio=eps, d_en_mm=den, s_Fn_mm=sFn * m, rho_F_mm=rhoF * m, h_Fe_mm=hFe * m,
                Y_F=YF, Y_S=YS, sigma_F0_MPa=Ft / (b * m) * YF * YS)


if __name__ == '__main__':
    if len(sys.argv) < 4:
        print(__doc__)
        sys.exit(2)
    args = [float(x) for x in sys.argv[1:]]
    r = sigma_f0(int(args[0]), int(args[1]), args[2], *args[3:])
    print(' '.join(f'{k} {v:.4g}' for k, v in r.items()))
