#!/usr/bin/env python3
"""Encode-and-send cost per byte, measured with valgrind's callgrind on the host and
scaled to the CM-530's 72 MHz Cortex-M3, compared with the thesis' 0.039 ms/byte.

Only bench_loop() is counted (--toggle-collect). Host x86-64 instructions are taken as a
proxy for Thumb-2 instructions; the Cortex-M3 at 72 MHz runs from flash with 2 wait
states, so one instruction costs about 1.0-1.5 cycles. Both ends are printed.
usage: encode_cost.py FW_ENCODE_BENCH OUT_DIR
"""
import os
import re
import subprocess
import sys

THESIS_MS_PER_BYTE = 0.039
MHZ = 72.0
N = 2000


def instructions(bench, kind, mode, outdir):
    out = os.path.join(outdir, f"callgrind.{kind}.{mode}")
    run = subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=bench_loop",
                          f"--callgrind-out-file={out}", bench, kind, mode, str(N)],
                         capture_output=True, text=True, check=True)
    m = re.search(r"(\d+) bytes", run.stdout)
    nbytes = int(m.group(1))
    total = None
    for line in open(out):
        if line.startswith("totals:") or line.startswith("summary:"):
            total = int(line.split()[1])
    return total, nbytes


def main():
    bench, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    print(f"Encode-and-send cost (callgrind, {N} messages each, legacy framing, GS1500M ESC Z framing)")
    print("  message     bytes   mode     instr/byte   ms/byte @72 MHz (CPI 1.0-1.5)   vs thesis 0.039")
    for kind in ("status", "text", "image"):
        for mode in ("encode", "send"):
            ir, nbytes = instructions(bench, kind, mode, outdir)
            per_byte = ir / nbytes
            lo = per_byte * 1.0 / (MHZ * 1000.0)
            hi = per_byte * 1.5 / (MHZ * 1000.0)
            print(f"  {kind:8s} {nbytes / N:8.0f}   {mode:6s} {per_byte:10.1f}    {lo:.5f} - {hi:.5f}"
                  f"               {THESIS_MS_PER_BYTE / hi:5.0f}x - {THESIS_MS_PER_BYTE / lo:.0f}x faster")
    return 0


if __name__ == "__main__":
    sys.exit(main())
