#!/usr/bin/env python3
"""Verification cost per datagram (HMAC-SHA-256 check of the trailer), measured with
valgrind's callgrind on the host (only bench_loop() is counted) and scaled to the CM-530's
72 MHz Cortex-M3. SHA-256 is 32-bit arithmetic: an x86-64 add, rotate or xor is one Thumb-2
instruction too (the M3 even folds a rotate into the next operation), but loads and stores of
the message schedule need more registers than the M3 has, so the estimate is printed for
1x-1.5x the host instructions at 1.0-1.5 cycles each.
usage: auth_cost.py FW_AUTH_BENCH OUT_DIR
"""
import os
import re
import subprocess
import sys

MHZ = 72.0
N = 500


def instructions(bench, payload, outdir):
    out = os.path.join(outdir, f"callgrind.auth.{payload}")
    subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=bench_loop",
                    f"--callgrind-out-file={out}", bench, str(payload), str(N)],
                   capture_output=True, text=True, check=True)
    for line in open(out):
        if line.startswith("totals:") or line.startswith("summary:"):
            return int(line.split()[1])
    raise SystemExit("no totals in " + out)


def main():
    bench, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    print(f"Verification cost per datagram (callgrind, {N} datagrams each, HMAC-SHA-256/128, libsodium)")
    print("  payload  datagram   host instr/datagram   Cortex-M3 cycles (1-1.5x instr, CPI 1.0-1.5)   ms @72 MHz")
    for payload in (30, 200, 1368):
        per = instructions(bench, payload, outdir) / N
        lo, hi = per * 1.0 * 1.0, per * 1.5 * 1.5
        print(f"  {payload:7d}  {payload + 32:8d}   {per:19.0f}   {lo:12.0f} - {hi:.0f}"
              f"                      {lo / (MHZ * 1000):.2f} - {hi / (MHZ * 1000):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
