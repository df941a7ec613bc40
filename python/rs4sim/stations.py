"""The stations of a running rs4sim, as rs4sim.v1.Run/Describe lists them (docs/rpc.md "Run").

    from rs4sim.stations import stations
    for s in stations("127.0.0.1:50051"):
        print(s.address, s.kind, s.name, s.services)   # 5 STATION_KIND_METRON metron [...]

One call: every station of the run with its kind (the rs4sim.v1.StationKind value's name), its
--device word and the services of the run that serve it. A run that observes no station of its
own (`rs4sim master`) lists none.
"""

from collections import namedtuple

Station = namedtuple("Station", "address kind name services")


def stations(address, timeout=10.0, root_certificates=None, token=None):
    """The run's stations at `address` (HOST:PORT), sorted by address."""
    from .harness import open_channel
    from .v1 import run_pb2, run_pb2_grpc

    channel = open_channel(address, root_certificates=root_certificates, token=token,
                           timeout=timeout)
    try:
        run = run_pb2_grpc.RunStub(channel).Describe(run_pb2.DescribeRunRequest(),
                                                      timeout=timeout)
    finally:
        channel.close()
    return [Station(s.address, run_pb2.StationKind.Name(s.kind), s.name, list(s.services))
            for s in run.stations]
