"""The PLC's side of `rs4sim run --link memory` from the Python harness (rs4sim.v1.Plc and the
PLC_* conditions): every output bit the PLC writes [RS4 manual §5.1.2] and what the PLC reads.
- boot() returns when the PLC reads OSSD 1 (it returned one cycle earlier, when the scanner
  sent it);
- a CRC2 fault: the PLC reads OSSD 0 (PLC_OSSD_OFF, PLC_PASSIVATED) while the scanner's OSSD
  stays on; `run` acknowledges by itself and the PLC reads 1 again;
- manual acknowledgement: the F-host waits in ack-required (PLC_ACK_REQUIRED) with OSSD 0 until
  acknowledge() [RS4 manual §7.3.2];
- field pair 0 is invalid: OSSD 0 (adapter error 0x2600) [RS4 manual §5.1.2]; pair 2 selected;
- the restart bit: after a field violation the restart interlock holds OSSD 0 until a pulse of
  the restart bit through the bus (0.3 s, inside 0.12..5 s) [RS4 manual §4.3, §5.1.2];
- Proxy-Enable reaches the RS4's output byte (DeviceState.output.proxy_enable).
Usage: python_plc_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import sys

from script_support import check, memory_rs4, require_grpc  # noqa: E402

require_grpc()
import grpc  # noqa: E402

rs4sim = sys.argv[1]
from rs4sim import error_details  # noqa: E402


with memory_rs4(rs4sim) as rs4:
    rs4.boot()
    check(rs4.plc_ossd(), f"boot() returned before the PLC reads OSSD 1: {rs4.plc()}")

    # A CRC2 fault: the PLC side passivates, the scanner does not notice.
    rs4.safety_fault("CORRUPT_CRC2")
    check(rs4.run_until("PLC_OSSD_OFF", 0.5), "the PLC reads OSSD 0 after a CRC2 fault")
    check(rs4.ossd(), "the scanner's OSSD stays on")
    check(not rs4.run_until("OSSD_OFF", 0.01), "OSSD_OFF follows the scanner, not the PLC")
    check(rs4.run_until("PLC_OSSD_ON", 2), "run acknowledges by itself: the PLC reads 1 again")

    # Manual acknowledgement: ACK_REQ until the operator acknowledges.
    mode = rs4.set_manual_acknowledge(True)
    check(mode.manual_acknowledge, f"{mode}")
    rs4.safety_fault("CORRUPT_CRC2")
    check(rs4.run_until("PLC_PASSIVATED", 0.5), "passivated")
    check(rs4.run_until("PLC_ACK_REQUIRED", 2), f"ack-required: {rs4.plc()}")
    rs4.advance(1)
    check(not rs4.plc_ossd() and rs4.plc().fhost_state == "ack-required", f"{rs4.plc()}")
    rs4.acknowledge()
    check(rs4.run_until("PLC_OSSD_ON", 1), f"after the acknowledgement: {rs4.plc()}")
    rs4.set_manual_acknowledge(False)

    # The field pair: 0 is invalid, 2 is selected.
    out = rs4.set_outputs(field_pair=0)
    check(out.output_byte & 0x07 == 0 and out.output.field_pair == 0, f"{out}")
    check(rs4.run_until("OSSD_OFF", 0.5), "field pair 0: OSSD 0 [RS4 manual §5.1.2]")
    rs4.set_outputs(field_pair=2)
    rs4.advance(1)
    check(rs4.state().active_field_pair == 2, f"pair {rs4.state().active_field_pair}")

    # The restart interlock through the bus.
    obstacle = rs4.violate_field("protective")
    check(rs4.run_until("OSSD_OFF", 0.5), "violated")
    rs4.remove(obstacle)
    check(not rs4.run_until("OSSD_ON", 1), "the restart interlock holds OSSD 0")
    before = rs4.now()
    out = rs4.pulse_restart(0.3)
    check(abs(rs4.now() - before - 0.3) < 1e-9 and not out.output.restart,
          f"the pulse ran 0.3 s and ended: {out}")
    check(rs4.run_until("PLC_OSSD_ON", 1), "restart by the bus: the PLC reads OSSD 1")

    # Proxy-Enable reaches the RS4; the restart bit held and refused for a pulse meanwhile.
    rs4.set_outputs(proxy_enable=True, restart=True)
    rs4.advance(0.05)
    state = rs4.state()
    check(state.output.proxy_enable and state.output.restart, f"the RS4 reads {state.output}")
    try:
        rs4.pulse_restart(0.2)
        check(False, "a pulse while the restart bit is 1 accepted")
    except grpc.RpcError as e:
        check(e.code() == grpc.StatusCode.FAILED_PRECONDITION, f"{e.code()}")
    rs4.set_outputs(restart=False)
    try:
        rs4.set_outputs(field_pair=8)
        check(False, "field pair 8 accepted")
    except grpc.RpcError as e:
        check(error_details(e)[1] == [("field_pair", "8 does not fit bits 2..0 (0..7)")],
              f"{error_details(e)}")
print("ok")
