#!/usr/bin/env python3
"""pyprofibus' FDL layer on the telegrams of bench_dp_fdl.cpp, for the speed ratio.

Times, in CPU ns per operation (process time, as Google Benchmark's "CPU" column; best of
several timeit repeats):
  decode         FdlTelegram.fromRawData(Data_Exchange request)
  encode         FdlTelegram_var(response).getRawData()
  decode+encode  both, i.e. what BM_DecodeReplyEncodeDataExchange does in C++

pyprofibus (GPL, https://github.com/mbuesch/pyprofibus) is not part of this repository:
pass the directory that contains its `pyprofibus` package as the first argument or in
PYPROFIBUS_PATH. Without it the script prints a message and exits with status 0.

    python3 bench/dp/fdl/pyprofibus_fdl_bench.py /path/to/pyprofibus
"""

import os
import sys
import time
import timeit

# SD2, DA 5, SA 2, FC 0x7D (SRD high, FCB, FCV), 6 output bytes: dx_request() in the C++ bench.
REQUEST = bytes([0x68, 0x09, 0x09, 0x68, 0x05, 0x02, 0x7D,
                 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0xE9, 0x16])
# SD2, DA 2, SA 5, FC 0x08 (DL, slave), 6 input bytes: dx_response() in the C++ bench.
RESPONSE = bytes([0x68, 0x09, 0x09, 0x68, 0x02, 0x05, 0x08,
                  0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x74, 0x16])
FC_DL = 0x08


def import_fdl(argv):
    path = argv[1] if len(argv) > 1 else os.environ.get("PYPROFIBUS_PATH", "")
    if not path or not os.path.isdir(os.path.join(path, "pyprofibus")):
        print("pyprofibus not found: pass its checkout directory as argument or in "
              "PYPROFIBUS_PATH (skipped)")
        return None
    sys.path.insert(0, path)
    from pyprofibus import fdl  # pylint: disable=import-outside-toplevel
    return fdl


def best_ns(stmt, number, repeat):
    runs = timeit.repeat(stmt, number=number, repeat=repeat, timer=time.process_time)
    return min(runs) / number * 1e9


def main(argv):
    fdl = import_fdl(argv)
    if fdl is None:
        return 0
    tele = fdl.FdlTelegram
    var = fdl.FdlTelegram_var

    def decode():
        return tele.fromRawData(REQUEST)

    def encode(du=REQUEST[7:13]):
        return var(da=2, sa=5, fc=FC_DL, dae=b"", sae=b"", du=du).getRawData()

    def decode_encode():
        req = tele.fromRawData(REQUEST)
        return var(da=req.sa, sa=req.da, fc=FC_DL, dae=b"", sae=b"", du=req.du).getRawData()

    # Same bytes as the C++ side, checked before timing.
    req = decode()
    assert (req.da, req.sa, req.fc, bytes(req.du)) == (5, 2, 0x7D, REQUEST[7:13])
    assert bytes(encode()) == RESPONSE and bytes(decode_encode()) == RESPONSE

    number = int(os.environ.get("PYPROFIBUS_BENCH_NUMBER", "200000"))
    repeat = int(os.environ.get("PYPROFIBUS_BENCH_REPEAT", "7"))
    print(f"pyprofibus FDL, Python {sys.version.split()[0]}, CPU time, "
          f"best of {repeat} x {number}")
    ns = 0.0
    for name, fn in (("decode", decode), ("encode", encode), ("decode+encode", decode_encode)):
        ns = best_ns(fn, number, repeat)
        print(f"  {name:<14} {ns:8.0f} ns/op")
    print(f"for bench_dp_fdl's x_pyprofibus counter: export PYPROFIBUS_NS={ns:.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
