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

# start <mode>: runs the device in the background; sets tty.
start() {
  bg_start polaris "$rs4sim" run --device polaris --link pty --model PL10 --beams 40 --mode "$1" \
    --address 1 --baud 19200 --blocked 9-13,25-34
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
echo "polaris_clients: all reads match"
