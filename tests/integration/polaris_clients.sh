#!/usr/bin/env bash
# Real Modbus clients, no code of ours on their side, against `rs4sim run --device polaris
# --link pty`: Debian's python3-pymodbus (3.0 API) and libmodbus's mbpoll read the FL4 and
# 485MB data of a known scene (objects 9-13 and 25-34 on a 40-beam PL10 barrier, slave 1).
#   tests/integration/polaris_clients.sh <path to rs4sim>
# Needs python3-pymodbus and mbpoll (build.sh installs them in test mode).
set -euo pipefail
rs4sim=$1
fail() { echo "polaris_clients: $*" >&2; exit 1; }

. "$(dirname "$0")/lib.sh"

# start <mode> [none]: runs the device in the background, objects 9-13 and 25-34 in the
# detection area ("none": a free area); sets tty.
start() {
  local blocked=(--blocked 9-13,25-34)
  [ "${2:-}" = none ] && blocked=()
  bg_start polaris "$rs4sim" run --device polaris --link pty --model PL10 --beams 40 --mode "$1" \
    --address 1 --baud 19200 "${blocked[@]}"
  bg_await polaris.out '^/dev/pts/'
  tty=$(grep -m1 '^/dev/pts/' "$dir/polaris.out")
  # the banner: the device serves its pty
  bg_await polaris.err 'Ctrl-C to stop'
}
stop() { bg_stop polaris TERM; }

pymodbus_read() {  # <tty> <count> -> the words, space-separated
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
from pymodbus.client import ModbusSerialClient
client = ModbusSerialClient(port=sys.argv[1], baudrate=19200, bytesize=8, parity="N",
                            stopbits=1, timeout=1)
if not client.connect():
    sys.exit("pymodbus: cannot open " + sys.argv[1])
reply = client.read_holding_registers(0x2000, int(sys.argv[2]), slave=1)
client.close()
if reply.isError():
    sys.exit("pymodbus: " + str(reply))
print(" ".join(str(w) for w in reply.registers))
PY
}

mbpoll_read() {  # <tty> <count> -> the words in hex (reference 8192, PDU addressing)
  mbpoll -m rtu -b 19200 -d 8 -P none -s 1 -a 1 -t 4:hex -0 -r 8192 -c "$2" -1 -o 1 "$1" |
    sed -n 's/^\[[0-9]*\]:[[:space:]]*//p' | tr 'a-f\n' 'A-F ' | sed 's/ $//'
}

expect() {  # <what> <got> <expected>
  [ "$2" = "$3" ] || fail "$1: got '$2', expected '$3'"
  echo "ok: $1 = $2"
}

start FL4
expect "pymodbus FL4" "$(pymodbus_read "$tty" 10)" "9 13 25 34 0 0 0 0 9 34"
expect "mbpoll FL4" "$(mbpoll_read "$tty" 10)" \
  "0x0009 0x000D 0x0019 0x0022 0x0000 0x0000 0x0000 0x0000 0x0009 0x0022"
stop

# 485MB: word 0 = beams 1-16 (9-13 interrupted: bits 8-12 clear) = 0xE0FF = 57599,
# word 1 = beams 17-32 (25-32: bits 8-15) = 0x00FF = 255, word 2 = beams 33-48 (33-34, and
# 41-48 padding) = 0xFFFC = 65532.
start 485MB
expect "pymodbus 485MB" "$(pymodbus_read "$tty" 3)" "57599 255 65532"
expect "mbpoll 485MB" "$(mbpoll_read "$tty" 3)" "0xE0FF 0x00FF 0xFFFC"
stop

# The configuration registers at 0x0100 (EXTENSION, docs/polaris.md "Configuration
# registers") written by the clients' own FC 6 and FC 16 encoders, and what the barrier
# answers after them [Modbus application protocol V1.1b3 §6.6, §6.12].
pymodbus_script() {  # <tty>, the Python on stdin; prints what it prints
  /usr/bin/python3 - "$1"
}
start FL4
expect "pymodbus FC 6 mode FL1, read back, FL1 data" "$(pymodbus_script "$tty" <<'PY'
import sys
from pymodbus.client import ModbusSerialClient
c = ModbusSerialClient(port=sys.argv[1], baudrate=19200, bytesize=8, parity="N", stopbits=1,
                       timeout=1)
assert c.connect()
w = c.write_register(0x0100, 1, slave=1)          # data mode 1 = FL1
assert not w.isError(), w
mode = c.read_holding_registers(0x0100, 1, slave=1)
data = c.read_holding_registers(0x2000, 2, slave=1)
bad_value = c.write_register(0x0100, 9, slave=1)  # no data mode 9: exception 03
bad_address = c.write_register(0x0200, 0, slave=1)  # outside the map: incorrect function, 07
c.close()
print(mode.registers[0], " ".join(map(str, data.registers)),
      bad_value.exception_code, bad_address.exception_code)
PY
)" "1 9 34 3 7"
# mbpoll's FC 16 (two values from 0x0102): direction reverse, detection object. Beam 1 is now
# at the far cap: physical 9-13 and 25-34 of 40 are transmitted 28-32 and 7-16 (41 - b), so
# FL1's overall pair is 7, 32.
mbpoll -m rtu -b 19200 -d 8 -P none -s 1 -a 1 -t 4 -0 -r 258 -1 -o 1 "$tty" 1 0 >/dev/null ||
  fail "mbpoll FC 16 write refused"
expect "mbpoll FC 16 direction reverse, FL1 data" "$(mbpoll_read "$tty" 2)" "0x0007 0x0020"
# With objects in the detection area the command register's start is refused, exception 04
# ("Make sure that there is no material ... in the detection area" [Polaris manual §7.2]).
expect "pymodbus calibration with beams interrupted" "$(pymodbus_script "$tty" <<'PY'
import sys
from pymodbus.client import ModbusSerialClient
c = ModbusSerialClient(port=sys.argv[1], baudrate=19200, bytesize=8, parity="N", stopbits=1,
                       timeout=1)
assert c.connect()
refused = c.write_register(0x0108, 1, slave=1)
status = c.read_holding_registers(0x0109, 1, slave=1)
c.close()
print(refused.exception_code, status.registers[0])
PY
)" "4 0"
stop

start FL4 none
# An auto-calibration from the command register (FC 6, 0x0108 = 1) in a free area: 16 s for
# 40 beams, the data answered with exception 06 meanwhile; a second start is busy too.
expect "pymodbus calibration busy" "$(pymodbus_script "$tty" <<'PY'
import sys
from pymodbus.client import ModbusSerialClient
c = ModbusSerialClient(port=sys.argv[1], baudrate=19200, bytesize=8, parity="N", stopbits=1,
                       timeout=1)
assert c.connect()
assert not c.write_register(0x0108, 1, slave=1).isError()
data = c.read_holding_registers(0x2000, 2, slave=1)
again = c.write_register(0x0108, 1, slave=1)
status = c.read_holding_registers(0x0109, 1, slave=1)
c.close()
print(data.exception_code, again.exception_code, status.registers[0])
PY
)" "6 6 1"
stop

# SIGUSR1: the autocal input, the same busy answer.
start FL4 none
bg_signal polaris USR1
# The signal is handled on the device's loop: the status register (0x0109) says when it
# has; then the data read is busy.
expect "pymodbus after SIGUSR1" "$(pymodbus_script "$tty" <<'PY'
import sys
import time
from pymodbus.client import ModbusSerialClient
c = ModbusSerialClient(port=sys.argv[1], baudrate=19200, bytesize=8, parity="N", stopbits=1,
                       timeout=1)
assert c.connect()
deadline = time.monotonic() + 10
while c.read_holding_registers(0x0109, 1, slave=1).registers[0] != 1:
    assert time.monotonic() < deadline, "no calibration within 10 s of SIGUSR1"
data = c.read_holding_registers(0x2000, 2, slave=1)
c.close()
print(data.exception_code)
PY
)" "6"
stop
echo "polaris_clients: all reads and writes match"
