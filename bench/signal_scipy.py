#!/usr/bin/env python3
"""scipy's figures for the work bench/signal_bench.cpp measures (issue #3).

    /usr/bin/python3 bench/signal_scipy.py            # Debian's python3-scipy

Envelopes |scipy.signal.hilbert(x)| and spectra |numpy.fft.rfft(x)| of records
of 30,000 / 29,999 / 32,768 / 4,194,304 / 4,194,301 samples, and the concrete
paper's Table-3 analysis: 9 frequencies x 6 sensors, two sets of 30,000-sample
records; envelopes, PCC of the signals and of the envelopes, spectra of all.
Prints the median of the repetitions in milliseconds (wall time, one thread).
"""
import statistics
import time

import numpy as np
import scipy
import scipy.signal


def record(n, seed):
    rng = np.random.default_rng(seed)
    f = 100e3 + 50e3 * (seed % 9)
    t = (np.arange(n) % 2000) * 1e-7
    tau = np.clip(t, 0, 5 / f)
    burst = np.where(t <= 5 / f, np.sin(2 * np.pi * f * tau) * 0.5 * (1 - np.cos(2 * np.pi * f * tau / 5)), 0.0)
    return burst + rng.normal(0.0, 0.05, n)


def median_ms(fn, repeats):
    fn()  # warm-up (numpy's FFT caches, page faults)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return 1e3 * statistics.median(times)


def pcc(a, b):
    return np.corrcoef(a, b)[0, 1]


def table3(a, b):
    total = 0.0
    for f in range(9):
        for s in range(6):
            x, y = a[f][s], b[f][s]
            ex, ey = np.abs(scipy.signal.hilbert(x)), np.abs(scipy.signal.hilbert(y))
            total += pcc(x, y) + pcc(ex, ey)
            np.abs(np.fft.rfft(x))
            np.abs(np.fft.rfft(y))
    return total


def main():
    print(f"scipy {scipy.__version__}, numpy {np.__version__}")
    for n in [30000, 29999, 32768, 4194304, 4194301]:
        x = record(n, 1)
        reps = 5 if n > 1_000_000 else 50
        env = median_ms(lambda: np.abs(scipy.signal.hilbert(x)), reps)
        spec = median_ms(lambda: np.abs(np.fft.rfft(x)), reps)
        print(f"envelope/{n}: {env:.3f} ms   spectrum/{n}: {spec:.3f} ms")
    a = [[record(30000, 100 * f + s) for s in range(6)] for f in range(9)]
    b = [[record(30000, 1000 + 100 * f + s) for s in range(6)] for f in range(9)]
    print(f"table3 (54 pairs x 30,000): {median_ms(lambda: table3(a, b), 7):.1f} ms")


if __name__ == "__main__":
    main()
