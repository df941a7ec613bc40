"""rs4sim.v1.Plc on `rs4sim master --grpc` (the RS4 in a second process on a pty): the field
pair the master sends changes through the API (BusMaster shows the output byte, the RS4
selects the pair), and the restart bit pulsed through the API gives the RS4 in its start
interlock its reset signal: the PLC reads OSSD 1 [RS4 manual §5.1.2].
Usage: python_master_plc_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import sys
import tempfile

from script_support import check, require_grpc, wait_for  # noqa: E402

require_grpc()

rs4sim = sys.argv[1]
from rs4sim import Master, Rs4  # noqa: E402
from rs4sim.process import Rs4simProcess  # noqa: E402


def station(master):
    return next(s for s in master.stations() if s.address == 4)


with tempfile.TemporaryDirectory() as tmp, \
        Rs4simProcess(["run", "--address", "4", "--link", "pty", "--boot-time", "1000",
                       "--grpc", "127.0.0.1:0"], executable=rs4sim) as run, \
        Rs4simProcess(["master", "--slave", "4", "--link", "serial", "--port", run.pty,
                       "--archive", os.path.join(tmp, "a.sqlite3"), "--grpc", "127.0.0.1:0"],
                      executable=rs4sim) as master_process, \
        Master(master_process.address) as master, Rs4(run.address) as rs4:
    wait_for("data exchange, PROFIsafe run", lambda: station(master).plc.fhost_state == "run", 30)
    # The RS4 booted and synchronised waits in its start interlock: OSSD 0 without a restart.
    wait_for("the RS4 measuring", lambda: rs4.state().rs4_state == "measuring", 30)
    check(not station(master).plc.input.ossd, "OSSD 0 before the restart")
    out = master.set_outputs(4, field_pair=2)
    check(out.output.field_pair == 2 and out.output_byte & 0x07 == 2, f"{out}")
    wait_for("the RS4 on pair 2", lambda: rs4.state().active_field_pair == 2, 30)
    check(station(master).output_byte & 0x07 == 2, f"{station(master)}")
    master.pulse_restart(4, 0.3)
    wait_for("OSSD 1 as the PLC reads it", lambda: station(master).plc.input.ossd, 30)
    check(not master.set_outputs(4).output.restart, "the pulse ended")
print("ok")
