"""`rs4sim run --grpc 0.0.0.0:0` with TLS and a bearer token, driven by the Python harness through
python3-grpcio (the rs4sim package): the test certificate of tests/rpc/data as the
client's root, the token of its token.txt; the right token answers (a service, health,
reflection), a wrong or missing one is UNAUTHENTICATED with its message, a plaintext client
fails; then `--grpc 127.0.0.1:0` with only RS4SIM_GRPC_TOKEN (no TLS, local credentials); a
line device's client (Polaris) over the same TLS and token as Rs4 (open_channel).
Usage: python_tls_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import json
import os
import signal
import ssl
import subprocess
import sys
import urllib.error
import urllib.request

from script_support import require_grpc

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Polaris, Rs4, open_channel  # noqa: E402

data = os.path.join(repo, "tests", "rpc", "data")
root = open(os.path.join(data, "localhost.crt"), "rb").read()
token = open(os.path.join(data, "token.txt")).readline().strip()


def serve(args, env=None, banner="grpc: listening on "):
    proc = subprocess.Popen([rs4sim, "run", "--link", "memory"] + args, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env)
    line = proc.stdout.readline()
    assert line.startswith(banner), (line, proc.stderr.read() if not line else "")
    return proc, int(line.rstrip().rstrip("/").split(":")[-1])


def stop(proc):
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=20)
    assert proc.returncode == 0, (proc.returncode, err)
    return err


def unauthenticated(call, message):
    try:
        call()
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.UNAUTHENTICATED, e.code()
        assert message in e.details(), e.details()
        return
    raise AssertionError("answered without the right token")


env = {k: v for k, v in os.environ.items() if k != "RS4SIM_GRPC_TOKEN"}
proc, port = serve(["--grpc", "0.0.0.0:0", "--grpc-tls-cert", os.path.join(data, "localhost.crt"),
                    "--grpc-tls-key", os.path.join(data, "localhost.key"),
                    "--grpc-token-file", os.path.join(data, "token.txt")], env)
try:
    address = f"127.0.0.1:{port}"
    rs4 = Rs4(address, root_certificates=root, token=token)
    assert rs4.now() > 0
    assert rs4.state().address == 4
    health = rs4.channel.unary_unary("/grpc.health.v1.Health/Check")(b"")
    assert health == b"\x08\x01", health.hex()
    call = rs4.channel.stream_stream(
        "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo")
    assert b"rs4sim.v1.Device" in b"".join(call(iter([b"\x3a\x00"])))

    unauthenticated(Rs4(address, root_certificates=root, token=token + "x").now,
                    "wrong bearer token")
    anonymous = open_channel(address, root_certificates=root)
    unauthenticated(lambda: anonymous.unary_unary("/grpc.health.v1.Health/Check")(b""),
                    "missing authorization metadata")
    plain = grpc.insecure_channel(address)
    try:
        plain.unary_unary("/grpc.health.v1.Health/Check")(
            b"", timeout=10, metadata=[("authorization", "Bearer " + token)])
        raise AssertionError("a plaintext client was answered by the TLS server")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.UNAVAILABLE, e.code()
finally:
    err = stop(proc)
assert "rs4sim: grpc: TLS, bearer token" in err, err

proc, port = serve(["--grpc", "127.0.0.1:0"], dict(env, RS4SIM_GRPC_TOKEN=token))
try:
    address = f"127.0.0.1:{port}"
    assert Rs4(address, token=token).now() > 0
    plain = grpc.insecure_channel(address)
    ok = plain.unary_unary("/grpc.health.v1.Health/Check")(
        b"", metadata=[("authorization", "Bearer " + token)])
    assert ok == b"\x08\x01", ok.hex()
    unauthenticated(lambda: plain.unary_unary("/grpc.health.v1.Health/Check")(b""),
                    "missing authorization metadata")
finally:
    stop(proc)

# A line device behind TLS and the token: its client opens the channel as Rs4 does.
tls = ["--grpc", "0.0.0.0:0", "--grpc-tls-cert", os.path.join(data, "localhost.crt"),
       "--grpc-tls-key", os.path.join(data, "localhost.key"),
       "--grpc-token-file", os.path.join(data, "token.txt")]
proc, port = serve(["--device", "polaris", "--address", "1"] + tls, env)
try:
    address = f"127.0.0.1:{port}"
    with Polaris(address, 1, root_certificates=root, token=token) as polaris:
        assert polaris.state().address == 1
        polaris.inject_fault("LATE", 0.04)
        assert polaris.state().late_ms == 40
    with Polaris(address, 1, root_certificates=root, token=token + "x") as wrong:
        unauthenticated(wrong.state, "wrong bearer token")
    # No TLS on the client: the channel never becomes ready (the old insecure channel's fate).
    try:
        Polaris(address, 1, timeout=2)
        raise AssertionError("a plaintext line-device client connected to the TLS server")
    except grpc.FutureTimeoutError:
        pass
finally:
    stop(proc)

# HTTPS: --http beyond loopback under --grpc's rule, the same certificate and token
proc, port = serve(["--http", "0.0.0.0:0", "--grpc-tls-cert", os.path.join(data, "localhost.crt"),
                    "--grpc-tls-key", os.path.join(data, "localhost.key"),
                    "--grpc-token-file", os.path.join(data, "token.txt")], env,
                   banner="http: listening on https://")
try:
    trusted = ssl.create_default_context(cafile=os.path.join(data, "localhost.crt"))
    url = f"https://127.0.0.1:{port}/api/rs4sim.v1.SimTime/Now"

    def post(context, authorization=None):
        request = urllib.request.Request(url, data=b"{}", method="POST",
                                         headers={"Content-Type": "application/json"})
        if authorization:
            request.add_header("Authorization", authorization)
        return urllib.request.urlopen(request, context=context, timeout=10)

    with post(trusted, "Bearer " + token) as answer:
        assert answer.status == 200, answer.status
        assert json.load(answer)["simulated"] is True
    try:
        post(trusted)
        raise AssertionError("answered without the token")
    except urllib.error.HTTPError as e:
        assert e.code == 401, e.code
        assert json.load(e)["code"] == 16
    # the page needs no token, but TLS all the same
    with urllib.request.urlopen(f"https://127.0.0.1:{port}/", context=trusted, timeout=10) as page:
        assert page.status == 200 and b"<html" in page.read().lower()
    # a client that trusts another certificate refuses the server
    other = ssl.create_default_context(cafile=os.path.join(data, "untrusted.crt"))
    try:
        post(other, "Bearer " + token)
        raise AssertionError("the untrusted certificate was accepted")
    except urllib.error.URLError as e:
        assert isinstance(e.reason, ssl.SSLCertVerificationError), e.reason
    # plain HTTP to the TLS port gets no HTTP answer
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=10) as page:
            raise AssertionError(f"plain HTTP answered {page.status}")
    except (urllib.error.URLError, ConnectionError, OSError) as e:
        assert not isinstance(e, urllib.error.HTTPError), e
finally:
    err = stop(proc)
assert "rs4sim: http: TLS, bearer token" in err, err
print("ok: TLS + bearer token through python3-grpcio, HTTPS through urllib")
