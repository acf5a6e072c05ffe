#!/usr/bin/python3
"""Times Debian python3-pywt's CWT of 100,000 samples at scales 1..16 (run with /usr/bin/python3).

Prints one line per variant: name, median wall seconds and median CPU seconds (this process)
over the repeats. bench_normalise_extras calls this and prints the ratios to the C++ transform
measured in the same run (docs/PERFORMANCE.md).
  mexh-conv, mexh-fft: pywt.cwt(x, 1..16, 'mexh', method=...)
  sym3-legacy: pywt 1.1.1's cwt refuses discrete wavelets, so the legacy MATLAB steps with
               pywt.integrate_wavelet + numpy.convolve, exactly what pywt.cwt does for
               continuous ones (THESIS-DIGEST section 3).
"""
import sys
import time

import numpy as np
import pywt


def median_time(function, repeats):
    walls = []
    cpus = []
    for _ in range(repeats):
        start = time.perf_counter()
        cpu = time.process_time()
        function()
        cpus.append(time.process_time() - cpu)
        walls.append(time.perf_counter() - start)
    return "%.6f %.6f" % (sorted(walls)[len(walls) // 2], sorted(cpus)[len(cpus) // 2])


def sym3_legacy(x, scales):
    int_psi, grid = pywt.integrate_wavelet('sym3', precision=10)
    step = grid[1] - grid[0]
    out = np.empty((len(scales), x.size))
    for i, scale in enumerate(scales):
        j = (np.arange(scale * (grid[-1] - grid[0]) + 1) / (scale * step)).astype(int)
        j = j[j < int_psi.size]
        coef = -np.sqrt(scale) * np.diff(np.convolve(x, int_psi[j][::-1]))
        d = (coef.size - x.size) / 2.0
        if d > 0:
            coef = coef[int(np.floor(d)):int(-np.ceil(d))]
        out[i] = coef
    return out


def main():
    samples = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    x = np.random.default_rng(5).standard_normal(samples)
    scales = np.arange(1, 17)
    print("mexh-conv", median_time(lambda: pywt.cwt(x, scales, 'mexh', method='conv'), repeats))
    print("mexh-fft", median_time(lambda: pywt.cwt(x, scales, 'mexh', method='fft'), repeats))
    print("sym3-legacy", median_time(lambda: sym3_legacy(x, scales), repeats))


if __name__ == "__main__":
    main()
