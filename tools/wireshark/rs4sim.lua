-- Wireshark/tshark dissector for rs4sim captures (docs/capture.md).
--
-- Layers: FDL telegrams [IEC 61158-4-3 frame formats]; the DP services by SAP and Data_Exchange
-- [IEC 61158-6-3]; DPV1 MSAC_C1/C2 Read/Write/Initiate/Abort and their error responses
-- [IEC 61158-6-3 MSAC_C1]; the PROFIsafe V1 5-byte PDU of an RS4/PROFIsafe (F-data byte, status
-- or control byte, consecutive number, CRC2) [RS4 manual §5.1]; and the RS4 block protocol of
-- slot 0, index 2/3 (flow-control byte, block length, block number, command code)
-- [RS4 manual §5.2.1], including the project's proxy commands (docs/proxy-protocol.md).
--
-- Bound to LINKTYPE_USER0 (147), rs4sim's default capture link type, and registered for
-- LINKTYPE_PROFIBUS_DL (257) where the Wireshark build maps that type.
-- Use:  wireshark -X lua_script:tools/wireshark/rs4sim.lua capture.pcap
--       tshark -X lua_script:tools/wireshark/rs4sim.lua -r capture.pcap -V

local p = Proto("rs4sim", "rs4sim PROFIBUS-DP / PROFIsafe / RS4")

local SD = { [0x10] = "SD1", [0x68] = "SD2", [0xA2] = "SD3", [0xDC] = "SD4 (token)",
             [0xE5] = "SC (short acknowledge)" }
local REQ_FN = { [0x0] = "Time Event", [0x3] = "SDA low", [0x4] = "SDN low", [0x5] = "SDA high",
                 [0x6] = "SDN high", [0x7] = "MSRD", [0x9] = "Request FDL Status",
                 [0xC] = "SRD low", [0xD] = "SRD high", [0xE] = "Request Ident",
                 [0xF] = "Request LSAP Status" }
local RSP_FN = { [0x0] = "OK", [0x1] = "UE (user error)", [0x2] = "RR (no resources)",
                 [0x3] = "RS (SAP not activated)", [0x8] = "DL (data low)",
                 [0x9] = "NR (no response data)", [0xA] = "DH (data high)",
                 [0xC] = "RDL", [0xD] = "RDH" }
local SAP = { [49] = "MSAC_C2 Initiate", [50] = "Alarm_Ack", [51] = "MSAC_C1", [53] = "Ext_User_Prm",
              [54] = "Master-Master", [55] = "Set_Slave_Add", [56] = "Rd_Inp", [57] = "Rd_Outp",
              [58] = "Global_Control", [59] = "Get_Cfg", [60] = "Slave_Diag", [61] = "Set_Prm",
              [62] = "Chk_Cfg" }
local DPV1_FN = { [0x48] = "Idle", [0x51] = "Data_Transport", [0x57] = "Initiate", [0x58] = "Abort",
                  [0x5C] = "Alarm_Ack", [0x5E] = "Read", [0x5F] = "Write" }
local FLOW_STATE = { [1] = "no communication path", [2] = "PC adapter attached",
                     [3] = "proxy executing", [4] = "normal operation", [5] = "no connection" }
local RS4_CMD = { [0x84] = "PROFI_CMD_ERROR", [0x90] = "PROFI_CMD_GET_VERSION",
                  [0x91] = "PROFI_CMD_GET_ERROR", [0x92] = "PROFI_CMD_GET_RS4_DATA",
                  [0x93] = "error in telegram", [0x94] = "PROFI_CMD_RESET",
                  [0x98] = "PROFI_CMD_PROXY_BEGIN (rs4sim)", [0x99] = "PROFI_CMD_PROXY_END (rs4sim)",
                  [0x14] = "COM_CMD_ALIVE", [0x23] = "COM_CMD_MESS_16_RT",
                  [0x24] = "request one scan", [0x53] = "COM_CMD_ERROR_OCCURE",
                  [0x54] = "COM_CMD_WARNING_OCCURE", [0x60] = "IDENTIFY (rs4sim)",
                  [0x61] = "UPLOAD_CHUNK (rs4sim)", [0x62] = "DOWNLOAD_BEGIN (rs4sim)",
                  [0x63] = "DOWNLOAD_CHUNK (rs4sim)", [0x64] = "DOWNLOAD_COMMIT (rs4sim)",
                  [0x65] = "DOWNLOAD_BREAK (rs4sim)" }

local f = {
  sd = ProtoField.uint8("rs4sim.fdl.sd", "Start delimiter", base.HEX, SD),
  le = ProtoField.uint8("rs4sim.fdl.le", "Length", base.DEC),
  da = ProtoField.uint8("rs4sim.fdl.da", "Destination", base.DEC),
  sa = ProtoField.uint8("rs4sim.fdl.sa", "Source", base.DEC),
  fc = ProtoField.uint8("rs4sim.fdl.fc", "Frame control", base.HEX),
  request = ProtoField.bool("rs4sim.fdl.request", "Request"),
  fcb = ProtoField.uint8("rs4sim.fdl.fcb", "FCB", base.DEC),
  fcv = ProtoField.uint8("rs4sim.fdl.fcv", "FCV", base.DEC),
  fn = ProtoField.string("rs4sim.fdl.function", "Function"),
  dsap = ProtoField.uint8("rs4sim.fdl.dsap", "DSAP", base.DEC, SAP),
  ssap = ProtoField.uint8("rs4sim.fdl.ssap", "SSAP", base.DEC),
  dsegment = ProtoField.uint8("rs4sim.fdl.dsegment", "Destination segment", base.DEC),
  ssegment = ProtoField.uint8("rs4sim.fdl.ssegment", "Source segment", base.DEC),
  fcs = ProtoField.uint8("rs4sim.fdl.fcs", "FCS", base.HEX),
  fcs_ok = ProtoField.bool("rs4sim.fdl.fcs_ok", "FCS correct"),
  du = ProtoField.bytes("rs4sim.fdl.du", "Data unit"),
  service = ProtoField.string("rs4sim.dp.service", "DP service"),
  dpv1_fn = ProtoField.uint8("rs4sim.dpv1.function", "DPV1 function", base.HEX),
  slot = ProtoField.uint8("rs4sim.dpv1.slot", "Slot", base.DEC),
  index = ProtoField.uint8("rs4sim.dpv1.index", "Index", base.DEC),
  length = ProtoField.uint8("rs4sim.dpv1.length", "Length", base.DEC),
  err_decode = ProtoField.uint8("rs4sim.dpv1.error_decode", "Error_Decode", base.HEX),
  err1 = ProtoField.uint8("rs4sim.dpv1.error_code_1", "Error_Code_1", base.HEX),
  err2 = ProtoField.uint8("rs4sim.dpv1.error_code_2", "Error_Code_2", base.HEX),
  flow = ProtoField.uint8("rs4sim.rs4.flow", "Flow-control byte", base.HEX),
  flow_state = ProtoField.uint8("rs4sim.rs4.flow_state", "Flow state", base.DEC, FLOW_STATE),
  flow_ready = ProtoField.bool("rs4sim.rs4.flow_ready", "Ready for WRITE"),
  flow_payload = ProtoField.bool("rs4sim.rs4.flow_payload", "Carries payload"),
  block_len = ProtoField.uint8("rs4sim.rs4.block_length", "Block length", base.DEC),
  block_no = ProtoField.uint16("rs4sim.rs4.block_number", "Block number", base.HEX),
  command = ProtoField.uint8("rs4sim.rs4.command", "Command", base.HEX, RS4_CMD),
  payload = ProtoField.bytes("rs4sim.rs4.payload", "Payload"),
  ps_data = ProtoField.uint8("rs4sim.ps.data", "F-data byte", base.HEX),
  ps_status = ProtoField.uint8("rs4sim.ps.status", "Status byte", base.HEX),
  ps_control = ProtoField.uint8("rs4sim.ps.control", "Control byte", base.HEX),
  ps_counter = ProtoField.uint8("rs4sim.ps.counter", "Consecutive number", base.DEC),
  ps_crc2 = ProtoField.uint16("rs4sim.ps.crc2", "CRC2", base.HEX),
}
p.fields = f

local function name(t, v, fallback) return t[v] or fallback or string.format("0x%02X", v) end

-- Whether a block continues a multi-block command: the last block is always 0xFFFF, also
-- when it is the only one [RS4 manual §5.2.1], so it is a continuation only after a block
-- 0..0xFFFE in the same direction. Computed on the first pass, kept per frame.
local open_commands = {}
local continuation = {}
local function is_continuation(pinfo, key, number)
  if not pinfo.visited then
    continuation[pinfo.number] = number ~= 0 and (number ~= 0xFFFF or open_commands[key] == true)
    open_commands[key] = number ~= 0xFFFF
  end
  return continuation[pinfo.number]
end

-- RS4 block protocol inside a DPV1 record of slot 0, index 2/3 [RS4 manual §5.2.1].
local function rs4_block(buf, tree, from_slave, pinfo, key)
  if buf:len() < 4 then return nil end
  local t = tree:add(p, buf, "RS4 block")
  local flow = buf(0, 1):uint()
  local ft = t:add(f.flow, buf(0, 1))
  if from_slave then
    ft:add(f.flow_ready, buf(0, 1), bit.band(flow, 1) ~= 0)
    ft:add(f.flow_payload, buf(0, 1), bit.band(flow, 2) ~= 0)
    ft:add(f.flow_state, buf(0, 1), bit.band(bit.rshift(flow, 4), 7))
  end
  t:add(f.block_len, buf(1, 1))
  local number = buf(2, 2):uint()
  t:add(f.block_no, buf(2, 2)):append_text(number == 0xFFFF and " (last)" or "")
  if buf:len() > 4 then
    local payload = buf(4)
    t:add(f.payload, payload)
    if not is_continuation(pinfo, key, number) then
      t:add(f.command, buf(4, 1))
      return name(RS4_CMD, buf(4, 1):uint())
    end
    return number == 0xFFFF and "last block" or ("block " .. number)
  end
  return "no payload"
end

-- DPV1 PDU [IEC 61158-6-3 MSAC_C1]. `request` is the FDL request direction.
local function dpv1(buf, tree, request, pinfo, key)
  if buf:len() < 1 then return "poll" end
  local fn = buf(0, 1):uint()
  local t = tree:add(p, buf, "DPV1")
  t:add(f.dpv1_fn, buf(0, 1)):append_text(" (" .. name(DPV1_FN, bit.band(fn, 0x7F)) ..
                                           (fn >= 0x80 and ", error)" or ")"))
  local text = name(DPV1_FN, bit.band(fn, 0x7F)) .. (request and ".req" or ".res")
  if fn >= 0x80 then
    if buf:len() >= 4 then
      t:add(f.err_decode, buf(1, 1)); t:add(f.err1, buf(2, 1)); t:add(f.err2, buf(3, 1))
      return text .. string.format(" error %02X %02X", buf(2, 1):uint(), buf(3, 1):uint())
    end
    return text .. " error"
  end
  if (fn == 0x5E or fn == 0x5F) and buf:len() >= 4 then
    t:add(f.slot, buf(1, 1)); t:add(f.index, buf(2, 1)); t:add(f.length, buf(3, 1))
    local slot, index = buf(1, 1):uint(), buf(2, 1):uint()
    text = text .. string.format(" slot %d index %d len %d", slot, index, buf(3, 1):uint())
    local has_data = (fn == 0x5F and request) or (fn == 0x5E and not request)
    if has_data and buf:len() > 4 and slot == 0 and (index == 2 or index == 3) then
      local b = rs4_block(buf(4):tvb(), tree, not request, pinfo, key)
      if b then text = text .. " [" .. b .. "]" end
    end
  end
  return text
end

-- PROFIsafe V1 PDU of the RS4 in Data_Exchange [RS4 manual §5.1].
local function profisafe(buf, tree, request)
  local t = tree:add(p, buf, "PROFIsafe V1")
  t:add(f.ps_data, buf(0, 1))
  t:add(request and f.ps_control or f.ps_status, buf(1, 1))
  t:add(f.ps_counter, buf(2, 1))
  t:add(f.ps_crc2, buf(3, 2))
  return string.format("F %02X %s %02X #%d", buf(0, 1):uint(), request and "ctrl" or "stat",
                       buf(1, 1):uint(), buf(2, 1):uint())
end

local function dp_service(buf, tree, request, dsap, ssap, pinfo, key)
  local sap = request and dsap or ssap
  if sap == nil then
    if buf:len() == 5 then return "Data_Exchange " .. profisafe(buf, tree, request) end
    return "Data_Exchange"
  end
  if sap == 51 or sap < 49 then return dpv1(buf, tree, request, pinfo, key) end
  return name(SAP, sap, "SAP " .. sap)
end

-- Address extension bytes after DA or SA with bit 7 [IEC 61158-4-3 addresses, SAPs]: bit 7 another
-- byte follows, bit 6 a segment address (else a SAP), bits 5..0 the number. DP sends one SAP
-- byte each. Returns the SAP, the segment and the position after the bytes.
local function extension(tvb, pos, body_end, root, sap_field, segment_field)
  local sap, segment
  while pos < body_end do
    local b = tvb(pos, 1):uint()
    if bit.band(b, 0x40) ~= 0 then
      segment = bit.band(b, 0x3F); root:add(segment_field, tvb(pos, 1), segment)
    else
      sap = bit.band(b, 0x3F); root:add(sap_field, tvb(pos, 1), sap)
    end
    pos = pos + 1
    if bit.band(b, 0x80) == 0 then break end
  end
  return sap, segment, pos
end

function p.dissector(tvb, pinfo, tree)
  local n = tvb:len()
  if n < 1 then return 0 end
  pinfo.cols.protocol = "rs4sim"
  local root = tree:add(p, tvb(), "rs4sim telegram")
  local sd = tvb(0, 1):uint()
  root:add(f.sd, tvb(0, 1))
  if sd == 0xE5 then pinfo.cols.info = "SC"; return n end
  if sd == 0xDC and n >= 3 then
    root:add(f.da, tvb(1, 1)); root:add(f.sa, tvb(2, 1))
    pinfo.cols.info = string.format("Token %d → %d", tvb(2, 1):uint(), tvb(1, 1):uint())
    return n
  end
  local h
  if sd == 0x68 and n >= 9 then root:add(f.le, tvb(1, 1)); h = 4
  elseif (sd == 0x10 or sd == 0xA2) and n >= 6 then h = 1
  else pinfo.cols.info = "malformed"; return n end
  local body_end = n - 2  -- FCS, ED
  local da, sa, fc = tvb(h, 1):uint(), tvb(h + 1, 1):uint(), tvb(h + 2, 1):uint()
  root:add(f.da, tvb(h, 1), bit.band(da, 0x7F))
  root:add(f.sa, tvb(h + 1, 1), bit.band(sa, 0x7F))
  local fct = root:add(f.fc, tvb(h + 2, 1))
  local request = bit.band(fc, 0x40) ~= 0
  fct:add(f.request, tvb(h + 2, 1), request)
  local fname
  if request then
    fct:add(f.fcb, tvb(h + 2, 1), bit.band(bit.rshift(fc, 5), 1))
    fct:add(f.fcv, tvb(h + 2, 1), bit.band(bit.rshift(fc, 4), 1))
    fname = name(REQ_FN, bit.band(fc, 0x0F))
  else
    fname = name(RSP_FN, bit.band(fc, 0x0F))
  end
  fct:add(f.fn, tvb(h + 2, 1), fname)
  local sum = 0
  for i = h, body_end - 1 do sum = (sum + tvb(i, 1):uint()) % 256 end
  root:add(f.fcs, tvb(body_end, 1))
  root:add(f.fcs_ok, tvb(body_end, 1), sum == tvb(body_end, 1):uint())
  local pos = h + 3
  local dsap, ssap, dseg, sseg
  if bit.band(da, 0x80) ~= 0 then
    dsap, dseg, pos = extension(tvb, pos, body_end, root, f.dsap, f.dsegment)
  end
  if bit.band(sa, 0x80) ~= 0 then
    ssap, sseg, pos = extension(tvb, pos, body_end, root, f.ssap, f.ssegment)
  end
  local info = string.format("%d → %d %s", bit.band(sa, 0x7F), bit.band(da, 0x7F), fname)
  local du_len = body_end - pos
  if du_len > 0 then root:add(f.du, tvb(pos, du_len)) end
  local carries_service = dsap ~= nil or ssap ~= nil or du_len > 0
  if dseg ~= nil or sseg ~= nil then
    root:add(f.service, "segment address (not DP)")
    info = info .. "  segment address (not DP)"
  elseif carries_service then
    local du = du_len > 0 and tvb(pos, du_len):tvb() or ByteArray.new(""):tvb("empty")
    local key = string.format("%d>%d", bit.band(sa, 0x7F), bit.band(da, 0x7F))
    local svc = dp_service(du, root, request, dsap, ssap, pinfo, key)
    root:add(f.service, svc)
    info = info .. "  " .. svc
  end
  pinfo.cols.info = info
  return n
end

DissectorTable.get("wtap_encap"):add(wtap.USER0, p)
if wtap.PROFIBUS_DL ~= nil then DissectorTable.get("wtap_encap"):add(wtap.PROFIBUS_DL, p) end

-- Byte-line captures (LINKTYPE_USER1, 148; docs/capture.md#byte-lines): a direction byte
-- (0 master → device, 1 device → master), a protocol byte, then the line's bytes:
--   1 GridScan CEDES frames: sync 43 45 44 45, SeqCnt, ID (bits 0..6 command, bit 7
--     curtain → controller), payload, CRC-32/MPEG-2 over SeqCnt..payload, LSB first
--     [GridScan manual §9.2];
--   2 METRON slave-mode messages: 02 [node] Length Command Data Checksum, the checksum
--     making Command + Data + checksum 0xFF mod 256 [METRON manual "No node", "With node"];
--     standard-mode reports 02 ... 03 shown as such;
--   3 Modbus RTU: address, function, data, CRC-16 LSB first [Modbus over Serial Line V1.02
--     §2.5.1.2], with the FC 3/4/16 fields [Modbus Application Protocol V1.1b3 §6];
--   4 the RS4's RS232 interface, shown as bytes [RS4 manual §5.2.3].
-- A received chunk that is not a whole frame is shown as bytes (the OS may split or join).
local line = Proto("rs4sim_line", "rs4sim byte line")
local DIRECTION = { [0] = "master → device", [1] = "device → master" }
local LINE_PROTOCOL = { [0] = "raw", [1] = "GridScan", [2] = "METRON", [3] = "Modbus RTU",
                        [4] = "RS4 RS232" }
local GS_CMD = { [0x10] = "Mode: Set polling", [0x11] = "Mode: Set full streaming",
                 [0x12] = "Mode: Set reduced streaming", [0x13] = "Mode: Set stand-by",
                 [0x14] = "Mode: Get current", [0x20] = "Info: Get version",
                 [0x21] = "Info: Get product information", [0x22] = "Info: Get count of elements",
                 [0x23] = "Info: Communication test", [0x24] = "Info: Get alignment value",
                 [0x25] = "Info: Request alignment mode", [0x30] = "Data: Reduced state",
                 [0x31] = "Data: Full state", [0x40] = "Safety: Test input",
                 [0x50] = "Config: Allow change", [0x51] = "Config: Set static",
                 [0x52] = "Config: Set blanking", [0x53] = "Config: Get current" }
local MT_CMD = { [0x01] = "Reset software", [0x02] = "Enable OSSD", [0x03] = "Disable OSSD",
                 [0x04] = "OSSD standby", [0x05] = "Start OSSD measurement",
                 [0x06] = "Stop OSSD measurement", [0x07] = "Start measurement",
                 [0x08] = "Stop measurement", [0x09] = "Request beam status",
                 [0x0A] = "Request measurements", [0x0B] = "Request configuration",
                 [0x0C] = "Request OSSD status", [0x0D] = "Request light curtain status",
                 [0xE1] = "E1 checksum or length", [0xE2] = "E2 length or argument",
                 [0xE3] = "E3 OSSD state", [0xE4] = "E4 no synchronism",
                 [0xE5] = "E5 no Start measurement" }
local MB_FN = { [1] = "Read Coils", [2] = "Read Discrete Inputs", [3] = "Read Holding Registers",
                [4] = "Read Input Registers", [5] = "Write Single Coil",
                [6] = "Write Single Register", [16] = "Write Multiple Registers" }
local lf = {
  direction = ProtoField.uint8("rs4sim.line.direction", "Direction", base.DEC, DIRECTION),
  protocol = ProtoField.uint8("rs4sim.line.protocol", "Protocol", base.DEC, LINE_PROTOCOL),
  bytes = ProtoField.bytes("rs4sim.line.bytes", "Bytes"),
  gs_seq = ProtoField.uint8("rs4sim.gridscan.seq", "SeqCnt", base.DEC),
  gs_id = ProtoField.uint8("rs4sim.gridscan.id", "ID", base.HEX),
  gs_cmd = ProtoField.uint8("rs4sim.gridscan.command", "Command", base.HEX, GS_CMD),
  gs_response = ProtoField.bool("rs4sim.gridscan.response", "Curtain → controller"),
  gs_payload = ProtoField.bytes("rs4sim.gridscan.payload", "Payload"),
  gs_crc = ProtoField.uint32("rs4sim.gridscan.crc", "CRC-32/MPEG-2", base.HEX),
  gs_crc_ok = ProtoField.bool("rs4sim.gridscan.crc_ok", "CRC correct"),
  mt_node = ProtoField.uint8("rs4sim.metron.node", "Node", base.DEC),
  mt_length = ProtoField.uint8("rs4sim.metron.length", "Length", base.DEC),
  mt_cmd = ProtoField.uint8("rs4sim.metron.command", "Command", base.HEX, MT_CMD),
  mt_data = ProtoField.bytes("rs4sim.metron.data", "Data"),
  mt_checksum = ProtoField.uint8("rs4sim.metron.checksum", "Checksum", base.HEX),
  mt_checksum_ok = ProtoField.bool("rs4sim.metron.checksum_ok", "Checksum correct"),
  mt_report = ProtoField.bytes("rs4sim.metron.report", "Standard-mode report"),
  mb_address = ProtoField.uint8("rs4sim.modbus.address", "Slave address", base.DEC),
  mb_fn = ProtoField.uint8("rs4sim.modbus.function", "Function", base.DEC, MB_FN),
  mb_exception = ProtoField.uint8("rs4sim.modbus.exception", "Exception code", base.HEX),
  mb_start = ProtoField.uint16("rs4sim.modbus.start", "Starting address", base.HEX),
  mb_quantity = ProtoField.uint16("rs4sim.modbus.quantity", "Quantity", base.DEC),
  mb_byte_count = ProtoField.uint8("rs4sim.modbus.byte_count", "Byte count", base.DEC),
  mb_data = ProtoField.bytes("rs4sim.modbus.data", "Data"),
  mb_crc = ProtoField.uint16("rs4sim.modbus.crc", "CRC-16", base.HEX),
  mb_crc_ok = ProtoField.bool("rs4sim.modbus.crc_ok", "CRC correct"),
}
line.fields = lf

local function crc32_mpeg2(tvb, from, to)  -- poly 0x04C11DB7, init 0xFFFFFFFF, no reflection
  local crc = 0xFFFFFFFF
  for i = from, to - 1 do
    crc = bit.bxor(crc, bit.lshift(tvb(i, 1):uint(), 24))
    for _ = 1, 8 do
      if bit.band(crc, 0x80000000) ~= 0 then
        crc = bit.bxor(bit.lshift(crc, 1), 0x04C11DB7)
      else
        crc = bit.lshift(crc, 1)
      end
    end
  end
  return bit.band(crc, 0xFFFFFFFF) % 0x100000000
end

local function crc16_modbus(tvb, from, to)  -- poly 0xA001 reflected, init 0xFFFF
  local crc = 0xFFFF
  for i = from, to - 1 do
    crc = bit.bxor(crc, tvb(i, 1):uint())
    for _ = 1, 8 do
      if bit.band(crc, 1) ~= 0 then crc = bit.bxor(bit.rshift(crc, 1), 0xA001)
      else crc = bit.rshift(crc, 1) end
    end
  end
  return crc
end

local function gridscan(tvb, tree)
  local n = tvb:len()
  if n < 10 or n > 20 or tvb(0, 4):uint() ~= 0x43454445 then return nil end
  local id = tvb(5, 1):uint()
  local cmd = bit.band(id, 0x7F)
  tree:add(lf.gs_seq, tvb(4, 1))
  local idt = tree:add(lf.gs_id, tvb(5, 1))
  idt:add(lf.gs_cmd, tvb(5, 1), cmd)
  idt:add(lf.gs_response, tvb(5, 1), bit.band(id, 0x80) ~= 0)
  if n > 10 then tree:add(lf.gs_payload, tvb(6, n - 10)) end
  local crc = tvb(n - 4, 4):le_uint()
  tree:add_le(lf.gs_crc, tvb(n - 4, 4))
  tree:add(lf.gs_crc_ok, tvb(n - 4, 4), crc == crc32_mpeg2(tvb, 4, n - 4))
  return string.format("GridScan SeqCnt %d %s%s", tvb(4, 1):uint(), name(GS_CMD, cmd),
                       bit.band(id, 0x80) ~= 0 and " (answer)" or "")
end

local function metron(tvb, tree)
  local n = tvb:len()
  if n < 4 or tvb(0, 1):uint() ~= 0x02 then return nil end
  local pos
  if 3 + tvb(1, 1):uint() == n then pos = 1            -- no node
  elseif n >= 5 and 4 + tvb(2, 1):uint() == n then     -- with node
    tree:add(lf.mt_node, tvb(1, 1)); pos = 2
  elseif tvb(n - 1, 1):uint() == 0x03 then
    tree:add(lf.mt_report, tvb(1, n - 2)); return "METRON standard-mode report"
  else return nil end
  local len = tvb(pos, 1):uint()
  tree:add(lf.mt_length, tvb(pos, 1))
  if len == 0 then return nil end
  local cmd = tvb(pos + 1, 1):uint()
  tree:add(lf.mt_cmd, tvb(pos + 1, 1))
  if len > 1 then tree:add(lf.mt_data, tvb(pos + 2, len - 1)) end
  local sum = 0
  for i = pos + 1, n - 1 do sum = (sum + tvb(i, 1):uint()) % 256 end
  tree:add(lf.mt_checksum, tvb(n - 1, 1))
  tree:add(lf.mt_checksum_ok, tvb(n - 1, 1), sum == 0xFF)
  return "METRON " .. name(MT_CMD, cmd)
end

local function modbus(tvb, tree, from_device)
  local n = tvb:len()
  if n < 4 then return nil end
  local fn = tvb(1, 1):uint()
  tree:add(lf.mb_address, tvb(0, 1))
  local fnt = tree:add(lf.mb_fn, tvb(1, 1), bit.band(fn, 0x7F))
  local body = n - 2
  if bit.band(fn, 0x80) ~= 0 then
    fnt:append_text(" (exception)")
    tree:add(lf.mb_exception, tvb(2, 1))
  elseif (fn == 3 or fn == 4) and from_device and n >= 5 then
    tree:add(lf.mb_byte_count, tvb(2, 1))
    if body > 3 then tree:add(lf.mb_data, tvb(3, body - 3)) end
  elseif (fn == 3 or fn == 4 or fn == 16) and n >= 8 then
    tree:add(lf.mb_start, tvb(2, 2))
    tree:add(lf.mb_quantity, tvb(4, 2))
    if fn == 16 and not from_device and n >= 9 then
      tree:add(lf.mb_byte_count, tvb(6, 1))
      if body > 7 then tree:add(lf.mb_data, tvb(7, body - 7)) end
    end
  elseif body > 2 then
    tree:add(lf.mb_data, tvb(2, body - 2))
  end
  tree:add_le(lf.mb_crc, tvb(body, 2))
  tree:add(lf.mb_crc_ok, tvb(body, 2), tvb(body, 2):le_uint() == crc16_modbus(tvb, 0, body))
  return string.format("Modbus slave %d %s%s", tvb(0, 1):uint(),
                       name(MB_FN, bit.band(fn, 0x7F)),
                       bit.band(fn, 0x80) ~= 0 and " exception" or "")
end

function line.dissector(tvb, pinfo, tree)
  if tvb:len() < 2 then return 0 end
  pinfo.cols.protocol = "rs4sim line"
  local root = tree:add(line, tvb())
  local dir = tvb(0, 1):uint()
  local proto = tvb(1, 1):uint()
  root:add(lf.direction, tvb(0, 1))
  root:add(lf.protocol, tvb(1, 1))
  local info
  if tvb:len() > 2 then
    local frame = tvb(2):tvb()
    root:add(lf.bytes, tvb(2))
    if proto == 1 then info = gridscan(frame, root)
    elseif proto == 2 then info = metron(frame, root)
    elseif proto == 3 then info = modbus(frame, root, dir == 1) end
  end
  pinfo.cols.info = string.format("%s  %s", name(DIRECTION, dir),
                                  info or name(LINE_PROTOCOL, proto) .. " bytes")
  return tvb:len()
end

DissectorTable.get("wtap_encap"):add(wtap.USER1, line)
