"""rs4sim: the Python client of the rs4sim simulator's gRPC API (docs/rpc.md).

    Rs4, GridScan, Metron, Polaris   one device of a running rs4sim (rs4sim.harness)
    GsdStations                      the GSD stations of a running rs4sim (rs4sim.gsd)
    GsdMaster                        the GSD slaves of a running `rs4sim master --grpc`
    Master                           a running `rs4sim master --grpc`: proxy and archive
    error_details, open_channel      a failed call's details; a channel with TLS/token
    Rs4simProcess                    start rs4sim, read its API address, end it (rs4sim.process)
    rs4sim.v1                        the generated protobuf and gRPC modules
    pytest fixtures                  rs4sim_memory, ... (rs4sim.pytest_plugin, loaded by pytest)

The harness names are imported on first use, so `rs4sim.process` and the pytest plugin load
without grpc.
"""

from .process import Rs4simError, Rs4simProcess, find_executable

try:
    from ._version import __version__
except ImportError:  # python/ itself: CMake writes _version.py into the tree it stages
    __version__ = "0+unstaged"

_HARNESS = ("Rs4", "Master", "GridScan", "Metron", "Polaris", "error_details", "open_channel",
            "pb", "pb_grpc", "archive_pb", "archive_grpc", "proxy_pb", "proxy_grpc", "dev_pb",
            "dev_grpc", "status_pb2", "error_details_pb2")

__all__ = ["Rs4simError", "Rs4simProcess", "find_executable", "__version__", *_HARNESS,
           "GsdStations", "GsdMaster"]


def __getattr__(name):
    if name in ("GsdStations", "GsdMaster"):
        from . import gsd
        return getattr(gsd, name)
    if name in _HARNESS:
        from . import harness
        return getattr(harness, name)
    raise AttributeError(f"module 'rs4sim' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_HARNESS) | {"GsdStations", "GsdMaster"})
