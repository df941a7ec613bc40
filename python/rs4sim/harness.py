"""The harness over rs4sim's gRPC API (docs/rpc.md): one class per device kind, the RPCs
in the words of the device's manual.

    from rs4sim import Rs4
    rs4 = Rs4("127.0.0.1:50051", station=4)
    rs4.boot()                       # data exchange, RS4 measuring, restart pulse, OSSD on
    obstacle = rs4.violate_field()   # the protective field
    assert rs4.run_until("OSSD_OFF", 0.5)

Time is in seconds, as floats, everywhere in the package (arguments and results: advance,
run_until, press_restart, exchange, receive, the faults' delays); the old spellings in
milliseconds or nanoseconds (`press_restart(ms=...)`, `now_ns()`, `advance(ms=...)`,
`late_ms=`) still work and warn with a DeprecationWarning. Fields of the answers keep the
protos' units in their names (`now_ns`, `sent_ns`).

Simulated time (advance, run_until) works where rs4sim runs on the manual clock
(`rs4sim run --link memory --grpc 127.0.0.1:0`; the pytest fixture `rs4sim_memory` starts
one). The stubs are the package's own rs4sim.v1 modules, generated when rs4sim is built.

With TLS and a bearer token (`--grpc-tls-cert`, `--grpc-tls-key`, `--grpc-token-file`):

    rs4 = Rs4("scanner-host:50051", root_certificates=open("ca.crt", "rb").read(),
              token=open("token.txt").readline().strip())
"""

import json
import warnings

import grpc

from ._units import deprecated, renamed, whole

try:
    from .v1 import rs4_pb2 as pb
except ModuleNotFoundError as missing:  # python/ itself, not the tree CMake stages
    if not (missing.name or "").startswith("rs4sim.v1"):
        raise
    raise ImportError(
        "rs4sim's gRPC stubs (rs4sim.v1) are not in this installation: they are generated "
        "when rs4sim is built; install the wheel the build makes (`cmake --build build "
        "--target rs4sim_python_wheel`, then `pip install --no-deps --no-index "
        "build/python/dist/rs4sim-*.whl` in a venv of /usr/bin/python3), not the source "
        "directory python/ (README, \"The Python package\")") from missing
from .v1 import rs4_pb2_grpc as pb_grpc  # noqa: E402
from .v1 import archive_service_pb2 as archive_pb  # noqa: E402,F401
from .v1 import archive_service_pb2_grpc as archive_grpc  # noqa: E402
from .v1 import proxy_service_pb2 as proxy_pb  # noqa: E402
from .v1 import proxy_service_pb2_grpc as proxy_grpc  # noqa: E402
from .v1 import devices_pb2 as dev_pb  # noqa: E402
from .v1 import devices_pb2_grpc as dev_grpc  # noqa: E402
from .v1 import plc_pb2 as plc_pb  # noqa: E402
from .v1 import diagnosis_pb2_grpc as diag_grpc  # noqa: E402
from .v1 import plc_pb2_grpc as plc_grpc  # noqa: E402
from ._googleapis.google.rpc import status_pb2, error_details_pb2  # noqa: E402


def error_details(error):
    """(code name, [(field, description)], [(type, subject, description)]) of a failed call."""
    violations, preconditions = [], []
    for key, value in error.trailing_metadata() or ():
        if key != "grpc-status-details-bin":
            continue
        status = status_pb2.Status.FromString(value)
        for any_detail in status.details:
            bad = error_details_pb2.BadRequest()
            failure = error_details_pb2.PreconditionFailure()
            if any_detail.Unpack(bad):
                violations += [(v.field, v.description) for v in bad.field_violations]
            elif any_detail.Unpack(failure):
                preconditions += [(v.type, v.subject, v.description) for v in failure.violations]
    return error.code().name, violations, preconditions


def _now(time_stub):
    """SimTime.Now in seconds."""
    return time_stub.Now(pb.Empty()).now_ns / 1e9


def _advance(time_stub, seconds):
    """SimTime.Advance by `seconds` (whole ms); the new time in seconds."""
    return time_stub.Advance(pb.AdvanceRequest(
        duration_ms=whole(seconds, 1000, "seconds"))).now_ns / 1e9


def _set_outputs(stub, address, field_pair, restart, proxy_enable):
    """Plc.SetOutputs with the bits given (None: kept)."""
    fields = {k: v for k, v in (("field_pair", field_pair), ("restart", restart),
                                ("proxy_enable", proxy_enable)) if v is not None}
    return stub.SetOutputs(plc_pb.SetPlcOutputsRequest(address=address, **fields))


def _pulse_restart(stub, address, seconds):
    """Plc.PulseRestart for `seconds` (whole ms)."""
    return stub.PulseRestart(plc_pb.PulseRestartRequest(
        address=address, duration_ms=whole(seconds, 1000, "seconds")))


class _Subscribed:
    """A server stream whose first event has been received: a gRPC call returns before the
    server has run its handler, and on the simulated clock a change made by the next RPC
    (an advance) would come before the subscription and never be seen. After cancel() (or
    the channel's close()) iterating ends quietly (StopIteration), as a finished stream does;
    any other end of the call still raises its grpc.RpcError."""

    def __init__(self, call, first=True):
        self._call = call
        self._cancelled = False
        self._first = [next(call)] if first else []

    def __iter__(self):
        """The stream itself (an iterator)."""
        return self

    def __next__(self):
        if self._first:
            return self._first.pop()
        try:
            return next(self._call)
        except grpc.RpcError as error:
            if self._cancelled and error.code() == grpc.StatusCode.CANCELLED:
                raise StopIteration from None
            raise

    def cancel(self):
        """Ends the stream: the server stops sending; iterating ends (no exception)."""
        self._cancelled = True
        self._call.cancel()


class _Client:
    """What every device class has: its channel, close() (also as a `with` block) and the
    rs4sim process it talks to when a fixture started it (rs4sim.process.Rs4simProcess)."""

    channel = None
    process = None

    def close(self):
        """Closes the channel; open event streams end with grpc.RpcError CANCELLED (a stream
        ended by its own cancel() ends quietly)."""
        self.channel.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def open_channel(address, root_certificates=None, token=None, timeout=10.0):
    """A ready channel to rs4sim's API (docs/rpc.md "Remote access"). root_certificates: the
    PEM bytes the server's certificate must chain to (TLS; the address's host must be in its
    names); token: sent as `authorization: Bearer <token>` on every call. A token without TLS
    goes over gRPC's local credentials (loopback only, plaintext on the wire)."""
    if root_certificates is None and token is None:
        channel = grpc.insecure_channel(address)
    else:
        creds = (grpc.ssl_channel_credentials(root_certificates=root_certificates)
                 if root_certificates is not None else grpc.local_channel_credentials())
        if token is not None:
            creds = grpc.composite_channel_credentials(
                creds, grpc.access_token_call_credentials(token))
        channel = grpc.secure_channel(address, creds)
    grpc.channel_ready_future(channel).result(timeout=timeout)
    return channel


class Rs4(_Client):
    """One RS4 of a running rs4sim, by station address."""

    def __init__(self, address, station=4, timeout=10.0, root_certificates=None, token=None):
        self.channel = open_channel(address, root_certificates, token, timeout)
        self.station = station
        self.device = pb_grpc.DeviceStub(self.channel)
        self.observation = pb_grpc.ObservationStub(self.channel)
        self.time = pb_grpc.SimTimeStub(self.channel)
        self.faults = pb_grpc.FaultsStub(self.channel)
        self.archive = archive_grpc.ArchiveStub(self.channel)
        self.plc_outputs = plc_grpc.PlcStub(self.channel)
        self.diagnostics = diag_grpc.DiagnosticsStub(self.channel)

    # ---- time ----------------------------------------------------------------------------
    def now(self):
        """The run's clock in seconds (SimTime.Now; a simulated clock starts at 3600 s)."""
        return _now(self.time)

    def advance(self, seconds):
        """Moves the simulated clock by `seconds` (whole ms; SimTime.Advance); returns the new
        time in seconds."""
        return _advance(self.time, seconds)

    def run_until(self, condition, timeout_s):
        """Runs the simulated clock until `condition` holds or timeout_s seconds passed; True
        when it held. The scanner's side: DATA_EXCHANGE, OSSD_ON, OSSD_OFF (the OSSD bit the
        RS4 sends), PROXY_REQUEST, RS4_MEASURING. The PLC's side (what the PLC program reads
        through the F-host; grpc.RpcError FAILED_PRECONDITION where the run has no PLC side):
        PLC_OSSD_ON, PLC_OSSD_OFF (0 also while passivated), PLC_PASSIVATED (passivated or
        waiting for ACK_REI), PLC_ACK_REQUIRED (ACK_REQ raised)."""
        req = pb.RunUntilRequest(address=self.station, timeout_ms=int(timeout_s * 1000),
                                 condition=pb.Condition.Value("CONDITION_" + condition))
        return self.time.RunUntil(req).reached

    # ---- observation -----------------------------------------------------------------------
    def state(self):
        """DeviceState (rs4.proto): its times in ns as the fields' names say (now_ns)."""
        return self.observation.GetState(pb.StationRequest(address=self.station))

    def ossd(self):
        """The scanner's OSSD bit of the input byte it sends (not what the PLC reads: plc())."""
        return self.state().input.ossd

    def plc(self):
        """What the PLC reads (simulated bus): F-host state, input byte and bits, counters."""
        return self.state().plc

    def plc_ossd(self):
        """The OSSD bit as the PLC program reads it: 0 while the F-host is passivated, whatever
        the scanner sends (ossd()); False where the run has no PLC side."""
        return self.state().plc.input.ossd

    def diagnosis(self):
        """The RS4's Slave_Diag decoded (DiagnosisView, no time): raw, station_status (the
        standard's names of the bits set: "Ext_Diag", "Prm_Fault", ...), master_address,
        ident_number, blocks (kind, data, summary) and texts, the RS4's words for it
        ("66 F_Dest_Add mismatch", "coming: 0x2600 ...")."""
        return self.diagnostics.GetDiagnosis(pb.StationRequest(address=self.station))

    def link_timing(self):
        """The station's replies on a real line (pty, serial, udp; None on the in-memory bus):
        replies, late (not sent, past --tsl), p50_ns/p99_ns/max_ns/mean_ns and the histogram
        (upper_ns, count) from the read that completed a request to the reply's write."""
        state = self.state()
        return state.link_timing if state.HasField("link_timing") else None

    def events(self, telegrams=False, queue_capacity=0, stations=None):
        """The event stream (an iterator of Event; .cancel() ends it): the current state
        first (StateChange with previous = ""), then every change, alarm, diagnosis change and,
        with telegrams=True, every telegram. A slow reader gets Event.dropped with the count.
        Returns once the server has subscribed (its snapshot has arrived), so nothing that
        the next call causes is missed; a bad request raises grpc.RpcError here."""
        addresses = [self.station] if stations is None else stations
        return _Subscribed(self.observation.StreamEvents(pb.StreamEventsRequest(
            addresses=addresses, telegrams=telegrams, queue_capacity=queue_capacity)))

    # ---- faults on the bus and in the safety layer -------------------------------------------
    def safety_fault(self, name, count=1):
        """name: CORRUPT_CRC2, REPEAT_NUMBER, SKIP_NUMBER, MUTE; count: the F-input PDUs
        affected (a number, no time)."""
        self.faults.InjectSafetyFault(pb.SafetyFaultRequest(
            address=self.station, fault=pb.SafetyFault.Value("SAFETY_FAULT_" + name), count=count))

    def clear_safety_faults(self):
        """Ends every safety fault of the station (no time)."""
        self.faults.ClearSafetyFaults(pb.StationRequest(address=self.station))

    def acknowledge(self):
        """The PLC operator's ACK_REI after a passivation (the simulated bus's F-host)."""
        self.faults.AcknowledgeReintegration(pb.StationRequest(address=self.station))

    # ---- what the PLC program writes (rs4sim.v1.Plc: run --link memory, master) -------------
    def set_outputs(self, field_pair=None, restart=None, proxy_enable=None):
        """The process output byte's bits [RS4 manual §5.1.2] from the next cycle on, those
        given (the others kept): field_pair 0..7 (0 and pairs the RS4 lacks provoke its
        error), restart and proxy_enable bools. Returns PlcOutputs (output_byte, output,
        manual_acknowledge). No time."""
        return _set_outputs(self.plc_outputs, self.station, field_pair, restart, proxy_enable)

    def pulse_restart(self, seconds=0.3):
        """The restart bit 1 for `seconds` (whole ms; the RS4 takes 0.12..5 s as the reset
        signal), then 0: the restart through the bus. On the simulated clock the call runs
        the clock through the pulse."""
        return _pulse_restart(self.plc_outputs, self.station, seconds)

    def set_manual_acknowledge(self, manual=True):
        """manual=True: after a passivation the F-host waits in ack-required (PLC reads
        fail-safe values) until acknowledge(); False: it acknowledges at once (run's
        default). No time."""
        return self.plc_outputs.SetAcknowledgeMode(plc_pb.SetAcknowledgeModeRequest(
            address=self.station, manual=manual))

    # ---- the world and the user's hands ----------------------------------------------------
    def violate_field(self, field="protective"):
        """An obstacle in the active pair's "protective" or "warning" field; returns its id."""
        kind = pb.FieldKind.Value("FIELD_KIND_" + field.upper())
        return self.device.ViolateField(
            pb.ViolateFieldRequest(address=self.station, field=kind)).obstacle_id

    def add_circle(self, x_mm, y_mm, radius_mm):
        """A circular obstacle, scanner coordinates in mm; returns its id."""
        shape = pb.CircleShape(centre=pb.PointMm(x=x_mm, y=y_mm), radius=radius_mm)
        return self.device.AddObstacle(
            pb.AddObstacleRequest(address=self.station, circle=shape)).obstacle_id

    def remove(self, obstacle_id):
        """Removes an obstacle by id (no time)."""
        self.device.RemoveObstacle(
            pb.RemoveObstacleRequest(address=self.station, obstacle_id=obstacle_id))

    def press_restart(self, seconds=None, *, ms=None):
        """Presses the restart button on X1 for `seconds` (default 0.2; whole ms, 0.12..5 s
        count as the reset signal [RS4 manual §4.3]). ms= is the deprecated spelling."""
        seconds = renamed(seconds, ms, "ms", "seconds", 1000, default=0.2)
        self.device.PressRestart(pb.PressRestartRequest(
            address=self.station, duration_ms=whole(seconds, 1000, "seconds")))

    def hold_restart(self):
        """Holds the restart button on X1 until release_restart(): LED3 red (state().led3_red)
        and the OSSD off meanwhile; the release counts as the reset signal only if the button
        was held 0.12..5 s ([RS4 manual §4.3]; time it with advance() on the manual clock)."""
        self.device.SetRestartButton(pb.SetRestartButtonRequest(address=self.station, pressed=True))

    def release_restart(self):
        """Releases the button hold_restart() holds (no time)."""
        self.device.SetRestartButton(
            pb.SetRestartButtonRequest(address=self.station, pressed=False))

    def leds(self):
        """The scanner's own LEDs and the adapter's: {"led3_red", "led5_yellow_blinking",
        "adapter": DeviceState.led, "adapter_lit": DeviceState.led_lit}."""
        s = self.state()
        return {"led3_red": s.led3_red, "led5_yellow_blinking": s.led5_yellow_blinking,
                "adapter": s.led, "adapter_lit": s.led_lit}

    def set_contamination(self, percent):
        """The window's contamination in percent, 0..100 (no time)."""
        self.device.SetContamination(
            pb.SetContaminationRequest(address=self.station, percent=percent))

    def inject_fault(self, name):
        """name: OSSD_CROSS_CIRCUIT, MOTOR_SPEED, INTERNAL_HARDWARE, DAZZLED."""
        self.device.InjectFault(
            pb.FaultRequest(address=self.station, fault=pb.Fault.Value("FAULT_" + name)))

    def set_pc_adapter(self, attached):
        """The optical PC adapter on (True) or off (no time)."""
        self.device.SetPcAdapter(pb.SetPcAdapterRequest(address=self.station, attached=attached))

    # ---- the unit and its parameter set ------------------------------------------------------
    def exchange_scanner(self, serial_number):
        """The manual's device exchange: power off, a new unit with factory settings and this
        serial number, power on (the RS4 boots again; the proxy downloads the archived set)."""
        self.device.ExchangeScanner(
            pb.ExchangeScannerRequest(address=self.station, serial_number=serial_number))

    def parameter_set(self):
        """The RS4's set as the parameter document (docs/param.md), a dict; its
        "device.serial_number" is the unit's."""
        return json.loads(self.device.GetParameterSet(pb.StationRequest(address=self.station)).json)

    def parameter_set_crc(self):
        """CRC-32 of the set as the proxy carries it: the archive's version CRC."""
        return self.device.GetParameterSet(
            pb.StationRequest(address=self.station)).transfer_crc32

    def set_parameter_set(self, document):
        """Writes a document (a dict or JSON text; any subset of the keys, "format" required)
        as the parametrisation tool does through the PC adapter; returns the set as it is now."""
        text = document if isinstance(document, str) else json.dumps(document)
        answer = self.device.SetParameterSet(
            pb.SetParameterSetRequest(address=self.station, json=text))
        return json.loads(answer.json)

    def boot(self, timeout_s=60):
        """Power-up to OSSD on: data exchange, RS4 measuring, the start-interlock restart pulse;
        returns when the PLC reads OSSD 1 (where the run has a PLC side; else when the scanner
        sends it). timeout_s: seconds of simulated time for each of the first two steps."""
        if not self.run_until("DATA_EXCHANGE", timeout_s):
            raise AssertionError("no data exchange")
        if not self.run_until("RS4_MEASURING", timeout_s):
            raise AssertionError("the RS4 did not reach measuring")
        if not self.run_until("OSSD_ON", 0.5):
            self.press_restart(0.2)
        if not self.run_until("OSSD_ON", 2):
            raise AssertionError("OSSD stays off after the restart pulse")
        if self.state().plc.present and not self.run_until("PLC_OSSD_ON", 1):
            raise AssertionError(f"the scanner's OSSD is on but the PLC reads 0: {self.plc()}")


class Master(_Client):
    """A running `rs4sim master --grpc`: its parameter proxy and the archive it writes."""

    def __init__(self, address, timeout=10.0, root_certificates=None, token=None):
        self.channel = open_channel(address, root_certificates, token, timeout)
        self.proxy = proxy_grpc.ProxyStub(self.channel)
        self.archive = archive_grpc.ArchiveStub(self.channel)
        self.bus_master = pb_grpc.BusMasterStub(self.channel)
        self.plc_outputs = plc_grpc.PlcStub(self.channel)

    def stations(self):
        """[BusStation]: each RS4 as the master sees it (address, dp_state, dp_error, plc: the
        F-host's state and counters, the input byte the PLC reads, dp: ProfiTrace's counters
        lost/syncs/repeats/illegal/negative; output_byte, f_diagnosis)."""
        return list(self.bus_master.ListStations(pb.Empty()).stations)

    def set_outputs(self, address, field_pair=None, restart=None, proxy_enable=None):
        """The output byte's bits for the RS4 at `address` from the next cycle on (as
        Rs4.set_outputs; no time): PlcOutputs."""
        return _set_outputs(self.plc_outputs, address, field_pair, restart, proxy_enable)

    def pulse_restart(self, address, seconds=0.3):
        """The restart bit 1 for `seconds` (whole ms; ends at the first master cycle after),
        then 0, for the RS4 at `address`; returns at once."""
        return _pulse_restart(self.plc_outputs, address, seconds)

    def proxy_status(self, addresses=()):
        """ProxyStatusResponse: bus, max_parallel, running, queue, stations (FB outputs)."""
        return self.proxy.GetStatus(proxy_pb.ProxyStatusRequest(addresses=list(addresses)))

    def watch_sync(self, addresses=(), until_done=True, timeout=None):
        """The progress stream (timeout: seconds, None = none; ProxyStationStatus items): the current status first, then
        each change; with until_done it ends once a sync seen running has ended. Returns
        once the current status has arrived (the server has subscribed)."""
        return _Subscribed(self.proxy.WatchSync(
            proxy_pb.WatchSyncRequest(addresses=list(addresses), until_sync_done=until_done),
            timeout=timeout))

    def history(self, address, bus="default"):
        """The archive's versions of one RS4, oldest first (ascending version number); their
        times as the fields' names say."""
        return self.archive.History(archive_pb.StationKey(bus=bus, address=address)).versions

    def note(self, version_id, text):
        """Replaces a version's comment; returns the VersionInfo."""
        return self.archive.Note(archive_pb.NoteRequest(version_id=version_id, note=text))

    def watch_versions(self, after_id=None, timeout=None):
        """The archive's change feed (timeout: seconds, None = none): every version as it is stored (by any master or
        workstation on the same archive), each once, in commit order (one station's in id
        order); first those after `after_id` when given. Returns once the server has
        subscribed; cancel() ends it."""
        request = (archive_pb.WatchVersionsRequest() if after_id is None
                   else archive_pb.WatchVersionsRequest(after_id=after_id))
        call = self.archive.WatchVersions(request, timeout=timeout)
        call.initial_metadata()  # sent once the feed is open: what is stored now is seen
        return _Subscribed(call, first=False)


class _LineDevice(_Client):
    """One RS-485 device of a running `rs4sim run --device gridscan|metron|polaris --grpc`
    (devices.proto), by its address on its line: GridScan 0, METRON its node (0 without
    node mode), Polaris its Modbus address."""

    _stub = None      # the generated stub class
    _fault_enum = ""  # e.g. "POLARIS_FAULT_"
    _fault_request = None
    _delay_field = ""

    def __init__(self, address, device_address, timeout=10.0, root_certificates=None,
                 token=None):
        self.channel = open_channel(address, root_certificates, token, timeout)
        self.address = device_address
        self.service = self._stub(self.channel)
        self.observation = pb_grpc.ObservationStub(self.channel)

    def state(self):
        """The device's state message (devices.proto): its times in ns as the names say."""
        return self.service.GetState(dev_pb.LineDeviceRequest(address=self.address))

    def set_blocked(self, numbers):
        """The interrupted elements/beams (1-based); all others free."""
        self.service.SetBlocked(dev_pb.SetBlockedRequest(address=self.address,
                                                         blocked=list(numbers)))

    def _fault(self, call, name, late_ms):
        fields = {"address": self.address,
                  "fault": getattr(dev_pb, self._fault_enum + name)}
        if late_ms:
            fields[self._delay_field] = late_ms
        call(self._fault_request(**fields))

    def inject_fault(self, name, late=None, *, late_ms=None, delay_ms=None):
        """name: the device's fault (its class lists them); late: LATE's delay in seconds,
        0.001..10 (whole ms). late_ms= and delay_ms= (milliseconds) are its deprecated
        spellings: accepted with a DeprecationWarning; given together they must agree
        (TypeError otherwise)."""
        if delay_ms is not None and late_ms is not None and delay_ms != late_ms:
            raise TypeError(f"inject_fault: delay_ms={delay_ms} differs from late_ms={late_ms} "
                            "(both deprecated spellings of late); give late (seconds) only")
        old_name = "late_ms" if delay_ms is None else "delay_ms"
        old = late_ms if delay_ms is None else delay_ms
        late = renamed(late, old, old_name, "late", 1000, default=0.0)
        self._fault(self.service.InjectFault, name, whole(late, 1000, "late"))

    def clear_fault(self, name):
        """Ends the fault `name` (no time)."""
        self._fault(self.service.ClearFault, name, 0)

    def events(self, telegrams=False, queue_capacity=0):
        """The shared event stream of this device (see Rs4.events): StateChange items; each
        Event's now_ns in ns."""
        return _Subscribed(self.observation.StreamEvents(pb.StreamEventsRequest(
            addresses=[self.address], telegrams=telegrams, queue_capacity=queue_capacity)))

    # ---- the simulated clock (rs4sim run --device X --link memory --grpc) ----------------
    def exchange(self, request, timeout=None, *, timeout_ms=None):
        """Sends `request` (bytes) on the simulated line and runs the clock until the reply
        has arrived or `timeout` seconds passed (whole ms; 0 or None: 1 s): an
        ExchangeResponse (answered, reply, sent_ns, arrived_ns, reply_start_ns, reply_end_ns,
        reply_after_ns, now_ns: nanoseconds). timeout_ms= is the deprecated spelling."""
        timeout = renamed(timeout, timeout_ms, "timeout_ms", "timeout", 1000, default=0.0)
        return self.service.Exchange(dev_pb.ExchangeRequest(
            address=self.address, request=bytes(request),
            timeout_ms=whole(timeout, 1000, "timeout")))

    def receive(self, wait=None, *, wait_ms=None):
        """Runs the clock `wait` seconds (whole ms; default 0), then the frames the device sent
        unasked (ReceivedFrame: frame, start_ns, end_ns in ns), oldest first. wait_ms= is the
        deprecated spelling."""
        wait = renamed(wait, wait_ms, "wait_ms", "wait", 1000, default=0.0)
        return list(self.service.Receive(dev_pb.ReceiveRequest(
            address=self.address, wait_ms=whole(wait, 1000, "wait"))).frames)

    def now(self):
        """The run's clock in seconds (SimTime.Now)."""
        return _now(pb_grpc.SimTimeStub(self.channel))

    def now_ns(self):
        """Deprecated: the run's clock in ns; use now() (seconds)."""
        deprecated("now_ns()", "now() (seconds)")
        return pb_grpc.SimTimeStub(self.channel).Now(pb.Empty()).now_ns

    def advance(self, seconds=None, *, ms=None):
        """Moves the simulated clock by `seconds` (whole ms; SimTime.Advance); returns the new
        time in seconds. ms= is the deprecated spelling (a number without a name is seconds,
        as for Rs4.advance)."""
        seconds = renamed(seconds, ms, "ms", "seconds", 1000)
        if seconds is None:
            raise TypeError("advance() needs the seconds to move the clock by")
        return _advance(pb_grpc.SimTimeStub(self.channel), seconds)


class GridScan(_LineDevice):
    """faults: LATE (late_ms; LATE_ANSWER is its old name), WRONG_SEQ, DIRECTION_BIT, BAD_CRC,
    INTERNAL_FAILURE, SILENT, CONFIG_NOT_SET, REPEAT_FRAMES, INSERT_FRAMES, TEST_IGNORED, MODE_ACTIVATION_FAILS;
    STUCK_FREE through stick_free/unstick."""
    _stub = dev_grpc.GridScanStub
    _fault_enum = "GRID_SCAN_FAULT_"
    _fault_request = dev_pb.GridScanFaultRequest
    _delay_field = "late_ms"

    def __init__(self, address, device_address=0, timeout=10.0, root_certificates=None,
                 token=None):
        super().__init__(address, device_address, timeout, root_certificates, token)

    def set_door(self, position):
        """The door's position, 0..elements (elements below its edge; no time)."""
        self.service.SetDoor(dev_pb.SetDoorRequest(address=self.address, position=position))

    def set_soiling(self, level):
        """The soiling level, 0..3 (no time)."""
        self.service.SetSoiling(dev_pb.SetSoilingRequest(address=self.address, level=level))

    def set_timing(self, cycle=None, *, cycle_ms=None):
        """t_CYCLE in seconds (whole ms) from the next power_cycle() on, inside the manual's
        band (22 elements: 0.018..0.040 s); grpc.RpcError INVALID_ARGUMENT outside. cycle_ms=
        is the deprecated spelling."""
        cycle = renamed(cycle, cycle_ms, "cycle_ms", "cycle", 1000)
        self.service.SetTiming(dev_pb.GridScanTimingRequest(
            address=self.address, cycle_ms=whole(cycle, 1000, "cycle")))

    def power_cycle(self, off=None, *, off_ms=None):
        """Mains off and on, `off` seconds later (whole ms; > 0 on the simulated clock only):
        the power-up again. off_ms= is the deprecated spelling."""
        off = renamed(off, off_ms, "off_ms", "off", 1000, default=0.0)
        self.service.PowerCycle(dev_pb.PowerCycleRequest(address=self.address,
                                                         off_ms=whole(off, 1000, "off")))

    def set_power(self, on):
        """Mains on (True) or off (no time)."""
        self.service.SetPower(pb.SetPowerRequest(address=self.address, on=on))

    def stick_free(self, elements):
        """Elements (1-based) that read free whatever is in front of them (STUCK_FREE)."""
        self.service.InjectFault(dev_pb.GridScanFaultRequest(
            address=self.address, fault=dev_pb.GRID_SCAN_FAULT_STUCK_FREE,
            elements=list(elements)))

    def unstick(self, elements=()):
        """Frees the given stuck elements again, or every one."""
        self.service.ClearFault(dev_pb.GridScanFaultRequest(
            address=self.address, fault=dev_pb.GRID_SCAN_FAULT_STUCK_FREE,
            elements=list(elements)))


class Metron(_LineDevice):
    """faults: SILENT, LATE (late_ms), BAD_CHECKSUM, WRONG_NODE, TRUNCATE."""
    _stub = dev_grpc.MetronStub
    _fault_enum = "METRON_FAULT_"
    _fault_request = dev_pb.MetronFaultRequest
    _delay_field = "late_ms"

    def __init__(self, address, device_address=0, timeout=10.0, root_certificates=None,
                 token=None):
        super().__init__(address, device_address, timeout, root_certificates, token)

    def set_synchronised(self, synchronised):
        """Emitter and receiver synchronised (True) or not (no time)."""
        self.service.SetSynchronised(dev_pb.SetSynchronisedRequest(
            address=self.address, synchronised=synchronised))

    def set_input(self, high):
        """The level of the curtain's input line (what its input type acts on)."""
        self.service.SetInput(dev_pb.SetInputRequest(address=self.address, high=high))

    def set_timing(self, scan_cycle=None, t_response=None, *, scan_cycle_ms=None,
                   t_response_ms=None):
        """The scan cycle (0.001..1 s) and Equation 3's t_response (0.001..2 s), in seconds
        (whole ms), from now on; grpc.RpcError INVALID_ARGUMENT outside. scan_cycle_ms= and
        t_response_ms= are the deprecated spellings."""
        scan_cycle = renamed(scan_cycle, scan_cycle_ms, "scan_cycle_ms", "scan_cycle", 1000)
        t_response = renamed(t_response, t_response_ms, "t_response_ms", "t_response", 1000)
        self.service.SetTiming(dev_pb.MetronTimingRequest(
            address=self.address, scan_cycle_ms=whole(scan_cycle, 1000, "scan_cycle"),
            t_response_ms=whole(t_response, 1000, "t_response")))


class Polaris(_LineDevice):
    """faults: BAD_CRC, SILENT (NO_ANSWER, its deprecated name, still works), LATE (late_ms)."""
    _stub = dev_grpc.PolarisStub
    _fault_enum = "POLARIS_FAULT_"
    _fault_request = dev_pb.PolarisFaultRequest
    _delay_field = "late_ms"

    def __init__(self, address, device_address=1, timeout=10.0, root_certificates=None,
                 token=None):
        super().__init__(address, device_address, timeout, root_certificates, token)

    def calibrate(self):
        """(No time argument.) Starts auto-calibration as the autocal input does: 0.4 s per beam, data reads get
        exception 06 meanwhile; grpc.RpcError FAILED_PRECONDITION while one runs or with a
        beam interrupted."""
        self.service.Calibrate(dev_pb.LineDeviceRequest(address=self.address))

    def set_timing(self, response_time=None, response_column=1, *, response_time_us=None):
        """One scan: response_time in seconds (0..1, whole µs), or 0 for the model table's
        maximum response time of column 1 or 2; grpc.RpcError INVALID_ARGUMENT outside.
        response_time_us= is the deprecated spelling."""
        response_time = renamed(response_time, response_time_us, "response_time_us",
                                "response_time", 1000000, default=0.0)
        self.service.SetTiming(dev_pb.PolarisTimingRequest(
            address=self.address, response_time_us=whole(response_time, 1000000,
                                                         "response_time"),
            response_column=response_column))

    def set_sw1(self, closed):
        """The SW1 contact: opened after 0.5..3 s starts an auto-calibration, after more than
        3 s the manual adjustment (on the simulated clock: advance() between the two)."""
        self.service.SetSw1(dev_pb.PolarisSw1Request(address=self.address, closed=closed))
