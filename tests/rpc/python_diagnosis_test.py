"""The decoded diagnosis of an RS4 over the API (Diagnostics.GetDiagnosis, Rs4.diagnosis()) on
a run in data exchange: the standard part by the standard's names (WD_On: the master's Set_Prm
switched the watchdog on; the always-1 bit not listed), our master's address 1, the RS4's
ident 0x5234 (Ident_Number of gsd/files/RSIM5234.gsd), and the RS4's status PDU
05 81 00 00 00 of [RS4 manual §6.3]: diagnosis 0, no fault, so no text. The texts of a fault
(66 wrong F_Dest_Add, 0x2600 ...) are checked on hand-written answers
(tests/rpc/diagnosis_view_test.cpp).
Usage: python_diagnosis_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import sys

from script_support import check, memory_rs4, require_grpc  # noqa: E402

require_grpc()

rs4sim = sys.argv[1]


with memory_rs4(rs4sim) as rs4:
    rs4.boot()
    d = rs4.diagnosis()
    check(d.address == 4 and d.error == "", f"{d}")
    check(d.raw == bytes([0x00, 0x0C, 0x00, 0x01, 0x52, 0x34, 0x05, 0x81, 0x00, 0x00, 0x00]),
          f"raw {d.raw.hex()}")
    check(list(d.station_status) == ["WD_On"], f"{list(d.station_status)}")
    check(d.master_address == 1 and d.ident_number == 0x5234, f"{d}")
    check([(b.kind, b.data) for b in d.blocks] == [("status", b"\x00")], f"{list(d.blocks)}")
    check(list(d.texts) == [], f"no fault, no text: {list(d.texts)}")
print("ok")
