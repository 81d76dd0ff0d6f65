#!/usr/bin/env python3
"""Prints the table of crates/column/src/vexp.rs: 2^(k/N), N = 128, as the exp of glibc >= 2.28 (the
algorithm of ARM's optimized-routines) stores it, computed here from its definition with
80-digit decimal arithmetic:

    H[k]  = 2^(k/N) rounded to the nearest double,
    T[k]  = (2^(k/N) - H[k]) / H[k] rounded to the nearest double,
    tab[2k] = bits(T[k]),  tab[2k+1] = bits(H[k]) - (k << 45)   (45 = 52 - log2 N).

Usage: scripts/exp-table.py > /tmp/table.rs; its output is the table of crates/column/src/vexp.rs as it
stands there, line for line (kept out of rustfmt).
The test `vexp_is_the_platform_exp_bit_for_bit` checks the result against libm's exp.
"""
import struct
from decimal import Decimal, getcontext

getcontext().prec = 80
N = 128


def bits(x):
    return struct.unpack("<Q", struct.pack("<d", x))[0]


def nearest(d):
    # CPython's float() of a decimal string is correctly rounded.
    return float(format(d, ".75e"))


words = []
for k in range(N):
    t = Decimal(2) ** (Decimal(k) / N)
    h = nearest(t)
    words.append(bits(nearest((t - Decimal(h)) / Decimal(h))))
    words.append((bits(h) - (k << 45)) % 2**64)
print("const TABLE: [u64; 2 * N] = [")
for i in range(0, len(words), 4):
    print("    " + ", ".join(f"0x{w:016x}" for w in words[i : i + 4]) + ",")
print("];")
