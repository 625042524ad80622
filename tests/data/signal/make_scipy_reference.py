#!/usr/bin/env python3
"""Reference values from scipy for tests/signal/scipy_reference_test.cpp.

Writes scipy_reference.csv: for records of several lengths (even, odd, 1-3,
primes, lengths with a large prime factor) the input x, Im of
scipy.signal.hilbert(x), its envelope |hilbert(x)|, and |numpy.fft.rfft(x)|
(NaN-free; the rfft column is empty past bin n//2).

Made with Debian's python3-scipy (scipy 1.10.1, numpy 1.24.2):
    apt-get install python3-scipy
    /usr/bin/python3 tests/data/signal/make_scipy_reference.py
"""
import csv
import pathlib

import numpy as np
import scipy
import scipy.signal

LENGTHS = [1, 2, 3, 4, 5, 8, 9, 16, 17, 29, 64, 65, 257, 262]


def record(n):
    i = np.arange(n, dtype=float)
    # A deterministic record with an offset, a chirp and an odd harmonic.
    return 0.25 + np.sin(0.7 * i + 0.002 * i * i) + 0.3 * np.cos(2.1 * i + 1.0)


def main():
    out = pathlib.Path(__file__).with_name("scipy_reference.csv")
    with out.open("w", newline="") as f:
        f.write(f"# scipy {scipy.__version__}, numpy {np.__version__}: made by make_scipy_reference.py\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["n", "i", "x", "hilbert_imag", "envelope", "rfft_abs"])
        for n in LENGTHS:
            x = record(n)
            z = scipy.signal.hilbert(x)
            X = np.abs(np.fft.rfft(x))
            for i in range(n):
                w.writerow([n, i, repr(float(x[i])), repr(float(z[i].imag)), repr(float(abs(z[i]))),
                            repr(float(X[i])) if i < len(X) else ""])


if __name__ == "__main__":
    main()
