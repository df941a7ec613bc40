"""`rs4sim run --link memory --grpc` driven by the Python harness (the rs4sim package, python/)
through python3-grpcio, a third-party gRPC client: boot in simulated time, a protective-field
violation and restart, the rich error details, the standard health service (its response
HealthCheckResponse{status = SERVING} is the fixed bytes 08 01) and server reflection
(ServerReflectionRequest{list_services = ""} is 3A 00; the answer names our services).
Usage: python_harness_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import signal
import sys

from script_support import require_grpc, spawn, state_changes

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Rs4, error_details  # noqa: E402

proc = spawn(rs4sim, "run", "--link", "memory", "--grpc", "127.0.0.1:0")
try:
    line = proc.stdout.readline()
    assert line.startswith("grpc: listening on 127.0.0.1:"), line
    address = line.split()[-1]
    rs4 = Rs4(address)

    # The scenario: violate the field, check OSSD, restart, check OSSD, inject a CRC
    # fault, check the PLC-relevant bits; the event stream watches all of it.
    events = rs4.events()
    start = rs4.now()  # the manual clock starts at 1 h, not 0
    rs4.boot()
    assert rs4.ossd(), "OSSD on after boot and restart pulse"
    boot_s = rs4.now() - start
    assert 30 <= boot_s < 40, f"the boot took {boot_s:.1f} s, not the RS4's ≈30 s of simulated time"
    obstacle = rs4.violate_field("protective")
    assert rs4.run_until("OSSD_OFF", 0.5)
    assert rs4.state().input.protective_field_violated
    rs4.advance(0.05)
    assert not rs4.plc().input.ossd, "the PLC reads the OSSD bit 0"
    rs4.remove(obstacle)
    assert not rs4.run_until("OSSD_ON", 1), "restart interlock holds the OSSD off"
    # The button held and released [RS4 manual §4.3]: LED3 red while held, the reset signal at
    # the release (0.3 s, inside 0.12..5 s).
    rs4.hold_restart()
    rs4.advance(0.3)
    assert rs4.leds()["led3_red"] and rs4.state().restart_button_held, rs4.leds()
    assert not rs4.ossd(), "not before the release"
    rs4.release_restart()
    assert not rs4.leds()["led3_red"]
    assert rs4.run_until("OSSD_ON", 1)
    rs4.advance(0.05)
    plc = rs4.plc()
    assert plc.present and plc.fhost_state == "run" and plc.input.ossd, plc

    rs4.safety_fault("CORRUPT_CRC2")
    rs4.advance(0.2)
    after = rs4.plc()
    assert after.crc_errors == plc.crc_errors + 1, after
    assert after.passivations == plc.passivations + 1, after
    rs4.safety_fault("MUTE")  # no fresh PDU: F_WD_Time expires
    rs4.advance(1)
    muted = rs4.state()
    assert muted.ossd and not muted.plc.input.ossd and muted.plc.input_byte == 0, muted.plc
    rs4.clear_safety_faults()
    rs4.advance(1)  # `run` acknowledges (ACK_REI) by itself
    assert rs4.plc().input.ossd and rs4.plc().fhost_state == "run", rs4.plc()

    ossd = state_changes(events, "ossd", 4)
    assert ossd == [("", "off"), ("off", "on"), ("on", "off"), ("off", "on")], ossd

    telegrams = rs4.events(telegrams=True)
    rs4.advance(0.1)
    directions = set()
    for event in telegrams:
        if event.HasField("telegram"):
            directions.add(event.telegram.direction)
            if len(directions) == 2:
                break
    telegrams.cancel()
    try:
        next(iter(rs4.events(queue_capacity=5)))
        raise AssertionError("queue_capacity 5 accepted")
    except grpc.RpcError as e:
        code, violations, _ = error_details(e)
        assert code == "INVALID_ARGUMENT" and violations[0][0] == "queue_capacity", violations

    try:
        rs4.set_contamination(150)
        raise AssertionError("contamination 150 % accepted")
    except grpc.RpcError as e:
        code, violations, _ = error_details(e)
        assert code == "INVALID_ARGUMENT" and violations[0][0] == "percent", (code, violations)
    try:
        rs4.acknowledge()  # `run` acknowledged by itself: nothing is waiting
        raise AssertionError("an ACK_REI with nothing to acknowledge was accepted")
    except grpc.RpcError as e:
        code, _, preconditions = error_details(e)
        assert code == "FAILED_PRECONDITION" and preconditions[0][0] == "STATE", preconditions
        assert "not ack-required" in preconditions[0][2], preconditions
    try:
        Rs4(address, station=9).state()
        raise AssertionError("station 9 answered")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.NOT_FOUND, e.code()

    # The unit and its set: the document as `rs4sim param` shows it (docs/param.md), a write
    # through the PC adapter, and the device exchange to a factory unit [RS4 manual §7.1].
    doc = rs4.parameter_set()
    assert doc["format"] == 1 and doc["response_time_ms"] == 80, doc
    crc = rs4.parameter_set_crc()
    doc = rs4.set_parameter_set({"format": 1, "response_time_ms": 160})
    assert doc["response_time_ms"] == 160 and rs4.parameter_set_crc() != crc, doc
    try:
        rs4.set_parameter_set({"format": 1, "response_time_ms": 100})
        raise AssertionError("a response time of 100 ms accepted")
    except grpc.RpcError as e:
        code, violations, _ = error_details(e)
        assert code == "INVALID_ARGUMENT" and violations[0][0] == "json", violations
        assert "$.response_time_ms" in violations[0][1], violations
    rs4.exchange_scanner(344865)
    doc = rs4.parameter_set()
    assert doc["device"]["serial_number"] == 344865 and doc["response_time_ms"] == 80, doc
    assert rs4.parameter_set_crc() == crc, "a new unit has the factory set"
    rs4.boot()

    health = rs4.channel.unary_unary("/grpc.health.v1.Health/Check")(b"")
    assert health == b"\x08\x01", health.hex()
    call = rs4.channel.stream_stream(
        "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo")
    answer = b"".join(call(iter([b"\x3a\x00"])))
    for service in (b"rs4sim.v1.Device", b"rs4sim.v1.Observation", b"rs4sim.v1.Faults",
                    b"rs4sim.v1.SimTime", b"grpc.health.v1.Health"):
        assert service in answer, (service, answer)
    print(f"ok: harness drove the RS4 through {rs4.now() - start:.1f} s of simulated time")
finally:
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=20)
    assert proc.returncode == 0, (proc.returncode, err)
    assert "served" in out, out
