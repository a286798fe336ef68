#!/usr/bin/env python3
"""relMSE and mean 8-bit sRGB error of an image against a reference (both PFM), as
src/test/resources/reference-pt/README.md defines them (glint.study.RelativeMse, ImageErrors.meanLevels).

  errors.py IMAGE.pfm REFERENCE.pfm
  errors.py --bound FACTOR REFERENCE.pfm RUN1.pfm RUN2.pfm   # FACTOR x the worse run's errors
"""
import sys

import numpy as np

from glint2mitsuba import read_pfm


def srgb(x):
    x = np.clip(x, 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def rel_mse(a, r):
    return float(np.mean((a - r) ** 2 / (r * r + 0.01)))


def mean_levels(a, r):
    return float(np.mean(np.abs(srgb(a) - srgb(r))) * 255)


if __name__ == "__main__":
    if sys.argv[1] == "--bound":
        factor, r = float(sys.argv[2]), read_pfm(sys.argv[3])
        runs = [read_pfm(p) for p in sys.argv[4:]]
        errs = [(rel_mse(a, r), mean_levels(a, r)) for a in runs]
        for p, e in zip(sys.argv[4:], errs):
            print("%s: relMSE %.4e  8-bit %.4f" % (p, e[0], e[1]))
        print("bound (x%g): relMSE %.3e  8-bit %.3f" % (factor, factor * max(e[0] for e in errs),
                                                         factor * max(e[1] for e in errs)))
    else:
        a, r = read_pfm(sys.argv[1]), read_pfm(sys.argv[2])
        print("relMSE %.4e  8-bit %.4f" % (rel_mse(a, r), mean_levels(a, r)))
