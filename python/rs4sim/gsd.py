"""The GSD stations of a running rs4sim (rs4sim.v1.GsdStations, docs/gsd.md "Harness API"):
`rs4sim run --device generic --gsd FILE --grpc 127.0.0.1:0`.

    from rs4sim import GsdStations
    gsd = GsdStations("127.0.0.1:50051")
    station = gsd.station(5)           # address, ident, modules with their I/O, DP state
    gsd.set_inputs(5, 1, b"\\x11\\x22")  # module in slot 1: exactly its input length
    gsd.outputs(5, 2)                  # what the master wrote to the module in slot 2
    gsd.set_online(5, False)           # off the bus; True puts it back
    gsd.f_module(5, 0).state           # a PROFIsafe F-module: "run", "passivated", ...
    gsd.set_f_inputs(5, 0, b"\\x01\\x00\\x00\\x00")  # the F-input data it reports
    gsd.inject_f_fault(5, 0, "CORRUPT_CRC2")  # also WRONG_NUMBER, REPEAT_NUMBER, DELAY, ...

On the simulated bus (`--link memory`) the clock and the bus faults:

    gsd.inject_bus_fault(5, "DROP", "FROM_STATION", count=1)  # the station's next reply lost
    gsd.advance(0.05)                  # 50 ms on the simulated clock: the master repeats
    gsd.clear_bus_faults()

The master side (rs4sim.v1.GsdMaster): `rs4sim master --gsd-slave 5:FILE --module 5:NAME ...
--grpc 127.0.0.1:0`.

    from rs4sim import GsdMaster
    master = GsdMaster("127.0.0.1:50052")
    master.slave(5).data_exchange      # the master's view: DP state, diagnosis, Set_Prm bytes
    master.set_outputs(5, 2, b"\xbe\xef")  # what the master sends to the module in slot 2
    master.inputs(5, 1)                # what it received from the module in slot 1

A PROFIsafe F-module has our F-host (docs/profisafe.md "Our master as F-host for GSD
F-devices"; `rs4sim master --manual-ack` leaves ACK_REQ to the operator):

    f = master.f_module(5, 0)          # f_state "run", mode "V1"/"V2", passivated, ack_req, ...
    master.set_f_outputs(5, 0, b"\x01\x00\x00\x00")  # the F-data of its next safety PDU
    master.f_module(5, 0).last_fault  # "CRC2 error" after a fault; f_state "ack-required"
    master.acknowledge(5, 0)           # ACK_REI: reintegration
"""

from ._units import renamed, whole
from .harness import _Client, _Subscribed, _advance, _now, open_channel, pb, pb_grpc
from .v1 import gsd_fdevice_pb2 as gsd_f_pb
from .v1 import gsd_pb2 as gsd_pb
from .v1 import gsd_pb2_grpc as gsd_grpc


class GsdStations(_Client):
    """Every GSD station of one rs4sim run, each by its station address."""

    def __init__(self, address, timeout=10.0, root_certificates=None, token=None):
        self.channel = open_channel(address, root_certificates, token, timeout)
        self.stub = gsd_grpc.GsdStationsStub(self.channel)
        self.observation = pb_grpc.ObservationStub(self.channel)
        self.time = pb_grpc.SimTimeStub(self.channel)

    def stations(self):
        """[GsdStation]: every station of the run (no time)."""
        return list(self.stub.ListStations(pb.Empty()).stations)

    def station(self, address):
        """GsdStation: ident, modules (by slot, from 0) with their I/O, DP state (no time)."""
        return self.stub.GetStation(pb.StationRequest(address=address))

    def set_inputs(self, address, slot, data):
        """The inputs (bytes, exactly the module's input length) of the module in `slot`
        (0-based: the first module of the Chk_Cfg is slot 0; no time)."""
        self.stub.SetInputs(gsd_pb.SetGsdInputsRequest(address=address, slot=slot,
                                                       data=bytes(data)))

    def inputs(self, address, slot):
        """The inputs of the module in `slot` (0-based) as the station sends them."""
        return self.station(address).modules[slot].inputs

    def outputs(self, address, slot):
        """What the master wrote to the module in `slot` (0-based)."""
        return self.station(address).modules[slot].outputs

    def set_online(self, address, online):
        """The station on the bus (True) or off it (no time)."""
        self.stub.SetOnline(gsd_pb.SetGsdOnlineRequest(address=address, online=online))

    def set_diagnosis(self, address, blocks=b"", ext_diag=False):
        """The station's extended diagnosis blocks (bytes) and Ext_Diag flag (no time)."""
        self.stub.SetDiagnosis(gsd_pb.SetGsdDiagnosisRequest(address=address, ext_diag=ext_diag,
                                                             blocks=bytes(blocks)))

    def raise_alarm(self, address, kind, slot=0, user_data=b""):
        """kind: "diagnostic", "process", "pull", "plug", "status", "update" (as the GSD
        declares them, GsdStation.alarms)."""
        alarm_type = gsd_pb.GsdAlarmType.Value("GSD_ALARM_TYPE_" + kind.upper())
        self.stub.RaiseAlarm(gsd_pb.RaiseGsdAlarmRequest(address=address, type=alarm_type,
                                                         slot=slot, user_data=bytes(user_data)))

    def link_timing(self, address):
        """The station's replies on a real line (pty, serial, udp; None on the in-memory bus),
        as Rs4.link_timing: replies, late (not sent, past --tsl), p50_ns/p99_ns/max_ns/mean_ns
        and the histogram (upper_ns, count)."""
        station = self.station(address)
        return station.link_timing if station.HasField("link_timing") else None

    # ---- the simulated bus (rs4sim run --gsd FILE --link memory --grpc) ------------------
    def now(self):
        """The run's clock in seconds (SimTime.Now)."""
        return _now(self.time)

    def advance(self, seconds):
        """Moves the simulated clock by `seconds` (whole ms; SimTime.Advance); returns the new
        time in seconds."""
        return _advance(self.time, seconds)

    def inject_bus_fault(self, address, kind, direction, count=1, delay=None, bit=0, *,
                         delay_ms=None):
        """GsdStations.InjectBusFault (the rules of Faults.InjectBusFault): kind "DROP",
        "CORRUPT" (bit: the bit flipped, modulo the frame's length) or "DELAY" (delay in
        seconds, 0.001..10, whole ms; delay_ms= is its deprecated spelling); direction "TO_STATION" (the master's requests) or "FROM_STATION" (the
        station's replies); the next `count` (1..1000000) telegrams. Returns the fault id. The
        simulated bus only: a real link refuses with FAILED_PRECONDITION."""
        delay = renamed(delay, delay_ms, "delay_ms", "delay", 1000, default=0.0)
        return self.stub.InjectBusFault(pb.BusFaultRequest(
            address=address, kind=pb.BusFaultKind.Value("BUS_FAULT_KIND_" + kind.upper()),
            direction=pb.Direction.Value("DIRECTION_" + direction.upper()), count=count,
            delay_ms=whole(delay, 1000, "delay"), bit=bit)).fault_id

    def clear_bus_faults(self):
        """GsdStations.ClearBusFaults: every bus fault of the run's simulated bus ends (those
        injected for its other stations too)."""
        self.stub.ClearBusFaults(pb.Empty())

    # ---- PROFIsafe F-modules (gsd_fdevice.proto, docs/profisafe.md "GSD F-devices") -------
    def f_modules(self, address):
        """[GsdFModule]: the station's F-devices (slot, mode "V1"/"V2", state, diagnosis and
        its text, consecutive number, the host's control bits, F-inputs/F-outputs, counters,
        pending faults; `host`: our master's F-host on the simulated bus)."""
        return list(self.stub.GetFModules(pb.StationRequest(address=address)).modules)

    def f_module(self, address, slot):
        """GsdFModule of the F-module in `slot` (0-based); KeyError if that slot has none."""
        for module in self.f_modules(address):
            if module.slot == slot:
                return module
        raise KeyError("station %d has no F-module in slot %d" % (address, slot))

    def set_f_inputs(self, address, slot, data):
        """The F-input data the F-module in `slot` reports (bytes, exactly its F-input
        length; sent while it runs; no time)."""
        self.stub.SetFInputs(gsd_pb.SetGsdInputsRequest(address=address, slot=slot,
                                                        data=bytes(data)))

    def set_f_outputs(self, address, slot, data):
        """The simulated bus: the F-output data our master's F-host sends to it (no time)."""
        self.stub.SetFOutputs(gsd_pb.SetGsdOutputsRequest(address=address, slot=slot,
                                                          data=bytes(data)))

    def inject_f_fault(self, address, slot, fault, count=1, delay=None, f_dest_add=0):
        """A fault of the F-device in `slot`: "CORRUPT_CRC2", "WRONG_NUMBER", "REPEAT_NUMBER"
        (the next `count` answers), "DELAY" (answers held back for `delay` seconds, whole ms)
        or "WRONG_F_DEST_ADD" (its address switch at `f_dest_add`, then a power-up; no
        time)."""
        kind = fault.upper()
        counted = kind in ("CORRUPT_CRC2", "WRONG_NUMBER", "REPEAT_NUMBER")
        self.stub.InjectFFault(gsd_f_pb.InjectGsdFFaultRequest(
            address=address, slot=slot, fault=gsd_f_pb.GsdFFault.Value("GSD_F_FAULT_" + kind),
            count=count if counted else 0,
            delay_ms=whole(delay, 1000, "delay") if delay is not None else 0,
            f_dest_add=f_dest_add))

    def clear_f_faults(self, address, slot):
        """The pending faults end; the address switch goes back (with a power-up)."""
        self.stub.ClearFFaults(gsd_f_pb.GsdFModuleRequest(address=address, slot=slot))

    def ack_f_host(self, address, slot):
        """The simulated bus: the operator acknowledges our master's F-host (ACK_REI); only
        while it raises ACK_REQ (state "ack-required")."""
        self.stub.AckFHost(gsd_f_pb.GsdFModuleRequest(address=address, slot=slot))

    def events(self, stations=(), telegrams=False):
        """Observation.StreamEvents for these stations (all: empty), as Rs4.events: the
        current items first (StateChange with previous = ""), then every change ("dp-state",
        "online", "inputs", "outputs", "ext-diag", "diagnosis", "diagnosis-text"; per
        F-module "fdevice-state", "fdevice-diagnosis", "f-inputs", "f-outputs" and on the
        simulated bus "fhost-state", each ending in ":<slot>" on a station with two
        F-modules or more)."""
        return _Subscribed(self.observation.StreamEvents(pb.StreamEventsRequest(
            addresses=list(stations), telegrams=telegrams)))


class GsdMaster(_Client):
    """The GSD slaves of one running `rs4sim master`, each by its station address."""

    def __init__(self, address, timeout=10.0, root_certificates=None, token=None):
        self.channel = open_channel(address, root_certificates, token, timeout)
        self.stub = gsd_grpc.GsdMasterStub(self.channel)

    def slaves(self):
        """[GsdSlave]: every GSD slave the master polls (no time)."""
        return list(self.stub.ListSlaves(pb.Empty()).slaves)

    def slave(self, address):
        """GsdSlave: the master's view of one slave (no time)."""
        return self.stub.GetSlave(pb.StationRequest(address=address))

    def set_outputs(self, address, slot, data):
        """What the master sends to the module in `slot` (0-based; bytes, exactly the
        module's output length; no time)."""
        self.stub.SetOutputs(gsd_pb.SetGsdOutputsRequest(address=address, slot=slot,
                                                         data=bytes(data)))

    def inputs(self, address, slot):
        """The module's inputs of the last Data_Exchange (b"" while not in data exchange)."""
        return self.slave(address).modules[slot].inputs

    def outputs(self, address, slot):
        """What the master sends to the module in `slot` (0-based)."""
        return self.slave(address).modules[slot].outputs

    # ---- PROFIsafe F-modules with our F-host ------------------------------------------------
    def f_modules(self, address):
        """[GsdMasterFModule]: the slave's PROFIsafe F-modules, slot order (no time): slot, mode
        ("V1", "V2"), f_state ("startup", "run", "passivated", "ack-required"), passivated,
        ack_req, last_fault, f_inputs, f_outputs, f_outputs_sent, the F-parameters written
        (parameters) and the fault counters (counters, a dict: "crc_errors", ...)."""
        return list(self.slave(address).f_modules)

    def f_module(self, address, slot=0):
        """GsdMasterFModule: the F-module in `slot` (0-based); KeyError when it is none."""
        for f in self.f_modules(address):
            if f.slot == slot:
                return f
        raise KeyError("slave %d has no F-module in slot %d" % (address, slot))

    def f_wd_time(self, address, slot=0):
        """The F-module's F_WD_Time in seconds (the F-host's watchdog)."""
        return self.f_module(address, slot).parameters.f_wd_time_ms / 1000.0

    def set_f_outputs(self, address, slot, data):
        """The F-output data (bytes, exactly the F-module's f_data_length) of its next safety
        PDU; 0 goes out instead while the F-host is passivated (no time)."""
        self.stub.SetFOutputs(gsd_pb.SetGsdOutputsRequest(address=address, slot=slot,
                                                          data=bytes(data)))

    def acknowledge(self, address, slot=0):
        """ACK_REI: the operator acknowledgement of the F-module's standing ACK_REQ; the
        F-host reintegrates the device. FAILED_PRECONDITION when no ACK_REQ waits (no time)."""
        self.stub.AcknowledgeF(gsd_pb.GsdFAcknowledgeRequest(address=address, slot=slot))
