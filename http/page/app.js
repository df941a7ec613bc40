// rs4sim live view (docs/http.md): the JSON API (POST /api/<Service>/<Method>) and the event
// stream (GET /api/events, Server-Sent Events). No library, nothing loaded from elsewhere.
"use strict";

const token = new URLSearchParams(location.hash.slice(1)).get("token") || "";
const SEGMENTS = 529;                     // [RS4 manual §2.3]: 529 segments of 0.36°
const angle = (n) => (-5.04 + 0.36 * n) * Math.PI / 180;
const NO_ECHO = 65535;

async function call(method, request = {}) {
  const headers = { "Content-Type": "application/json" };
  if (token) headers.Authorization = "Bearer " + token;
  const r = await fetch("/api/" + method, { method: "POST", headers, body: JSON.stringify(request) });
  const body = await r.json();
  if (!r.ok) throw Object.assign(new Error(body.message || r.statusText), { status: r.status, body });
  return body;
}

const $ = (id) => document.getElementById(id);
const el = (tag, attrs = {}, text) => {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
};
const svg = (tag, attrs = {}) => {
  const e = document.createElementNS("http://www.w3.org/2000/svg", tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
};

// ---- what the run serves and runs (rs4sim.v1.Run/Describe, asked once) ----------------------
let served = new Set();
const serves = (service) => served.has("rs4sim.v1." + service);

// ---- the run's clock: times are shown since the run began -------------------------------------
let clockStart = 0;
let simulatedRun = false;  // SimTime's start_ns: the run's clock when it began (not 0 when simulated)
const sinceStart = (ns) => ((Number(ns) - clockStart) / 1e9).toFixed(3) + " s";

// ---- the stations -------------------------------------------------------------------------
const stations = new Map();  // address -> { kind, values: {what: to}, state, alarms, diags }
let selected = null;         // the RS4 shown in the panel

function station(address) {
  if (!stations.has(address)) {
    stations.set(address, { kind: "", values: {}, state: null, alarms: "", diags: 0 });
  }
  return stations.get(address);
}

const pill = (text, cls) => `<span class="pill ${cls || ""}">${text || "–"}</span>`;
// The DP state in the standard's words [IEC 61158-6-3 slave state machine]: the slave's own
// (the event stream, GsdStations) and the master's view of it (BusMaster: DataExchange,
// WaitPrm, ...) shown alike, with one colour for data exchange.
const DP_STATE_NAMES = { DataExchange: "Data_Exch", WaitPrm: "Wait_Prm", WaitCfg: "Wait_Cfg",
  PowerOn: "Power_On" };
const dpName = (v) => DP_STATE_NAMES[v] || v;
function dpClass(v) { return dpName(v) === "Data_Exch" ? "ok" : v ? "warn" : ""; }
function fClass(v) { return !v ? "" : /run|data/i.test(v) ? "ok" : /fail|passiv|error/i.test(v) ? "bad" : "warn"; }

function renderStations() {
  const body = $("stations").tBodies[0];
  $("stations-empty").hidden = stations.size > 0;
  for (const address of [...stations.keys()].sort((a, b) => a - b)) {
    const s = stations.get(address);
    let row = body.querySelector(`tr[data-address="${address}"]`);
    if (!row) {
      row = el("tr", { class: "station", "data-address": address });
      row.addEventListener("click", () => select(address));
      body.append(row);
      [...body.rows].sort((a, b) => a.dataset.address - b.dataset.address).forEach((r) => body.append(r));
    }
    const m = s.master;  // `master`: the master's own view (BusMaster.ListStations)
    const plc = s.state && s.state.plc && s.state.plc.present ? s.state.plc
      : m && m.plc && m.plc.present ? m.plc : null;
    const v = m ? Object.assign(masterValues(m), s.values) : s.values;
    row.dataset.state = v["dp-state"] || (v.powered === "off" ? "off" : "unknown");
    if (v.ossd !== undefined) row.dataset.ossd = v.ossd;
    row.dataset.kind = s.kind;
    // The master's counters in ProfiTrace's names (docs/http.md "Station counters").
    const dp = plc && plc.dp ? plc.dp : null;
    for (const k of ["lost", "syncs", "repeats", "illegal", "negative"]) {
      if (dp) row.dataset[k] = Number(dp[k] || 0); else delete row.dataset[k];
    }
    const n = (k) => (dp ? Number(dp[k] || 0) : "–");
    row.classList.toggle("selected", address === selected);
    row.innerHTML = [
      `<td>${address}</td>`, `<td>${s.kind || "–"}</td>`,
      `<td>${pill(dpName(v["dp-state"]), dpClass(v["dp-state"]))}</td>`,
      `<td>${fdeviceCell(v, plc)}</td>`,
      `<td>${v.ossd === undefined ? "–" : pill(v.ossd, v.ossd === "on" ? "ok" : "bad")}</td>`,
      `<td>${v["rs4-state"] || v.state || (v.powered === "off" ? "off" : v.online === "no" ? "off the bus" : v.online === "yes" ? "online" : "–")}</td>`,
      `<td>${proxyText(s)}</td>`,
      `<td><code>${v["input-byte"] || v.inputs || ""}</code></td>`, `<td><code>${v["output-byte"] || v.outputs || ""}</code></td>`,
      `<td>${plc ? plc.crcErrors : "–"}</td>`, `<td>${plc ? plc.numberErrors : "–"}</td>`,
      `<td>${plc ? plc.watchdogTimeouts : "–"}</td>`, `<td>${plc ? plc.passivations : "–"}</td>`,
      `<td class="count">${n("lost")}</td>`, `<td class="count">${n("syncs")}</td>`,
      `<td class="count">${n("repeats")}</td>`, `<td class="count">${n("illegal")}</td>`,
      `<td class="count">${n("negative")}</td>`,
      `<td>${s.alarms || "–"}</td>`, `<td>${s.diags}</td>`,
    ].join("");
  }
}

// The RS4's PROFIsafe state and, where the run has the PLC side, the F-host's. A simulated bus
// is all in this process: without a PLC side it has no F-host, and the RS4 waiting for one
// (its watchdog expired: "fault") is shown as that, not as a fault. On a real link the F-host
// is elsewhere and the device's state is shown as it is.
function fdeviceCell(v, plc) {
  const f = v["fdevice-state"];
  if (!f) return plc ? pill("F-host " + plc.fhostState, fClass(plc.fhostState)) : "–";
  if (!plc && simulatedRun && fClass(f) !== "ok") return pill("no F-host on this bus", "");
  return pill(f, fClass(f)) + (plc ? " " + pill("F-host " + plc.fhostState, fClass(plc.fhostState)) : "");
}

// A station as `master`'s class 1 master and F-host see it, in the event stream's item names
// (its DP state in the master's words: DataExchange, WaitPrm, ...).
function masterValues(m) {
  const plc = m.plc || {};
  return { "dp-state": m.dpState, ossd: plc.input && plc.input.ossd ? "on" : "off",
    "input-byte": hex(plc.inputByte || 0).toLowerCase(),
    "output-byte": hex(m.outputByte || 0).toLowerCase(), "rs4-state": m.dpError || "" };
}

async function pollMaster() {
  try {
    const list = await call("rs4sim.v1.BusMaster/ListStations");
    for (const m of list.stations || []) {
      const s = station(m.address);
      s.master = m;
      if (!s.kind) s.kind = "rs4 (master)";
    }
    scheduleRender();
    return true;
  } catch (err) { return false; }  // not `master`: no BusMaster service in this run
}

// The proxy's step and progress (Proxy.GetStatus on `master`), else the RS4's proxy phase.
function proxyText(s) {
  const p = s.proxy;
  if (!p) return s.values["proxy-phase"] || "–";
  const total = Number(p.bytesTotal);
  const pct = total > 0 ? ` ${Math.round(100 * Number(p.bytesDone) / total)} %` : "";
  return `${p.step}${p.running ? " (" + p.direction + ")" : ""}${pct}`;
}

async function pollProxy() {
  try {
    const status = await call("rs4sim.v1.Proxy/GetStatus");
    for (const p of status.stations || []) {
      const s = station(p.address);
      s.proxy = p;
      if (!s.kind) s.kind = "rs4 (proxy)";
    }
    scheduleRender();
    return true;
  } catch (err) { return false; }  // no Proxy service in this run
}

function log(text) {
  const li = el("li", {}, text);
  $("log").prepend(li);
  while ($("log").children.length > 200) $("log").lastChild.remove();
}

function onEvent(e) {
  const address = e.address || 0;
  const s = station(address);
  const t = sinceStart(e.nowNs);
  if (e.state) {
    s.values[e.state.what] = e.state.to;
    if (e.state.from) log(`${t}  #${address}  ${e.state.what}: ${e.state.from} → ${e.state.to}`);
  } else if (e.alarm) {
    s.alarms = `${e.alarm.pending}/${e.alarm.outstanding}`;
    log(`${t}  #${address}  alarm: ${e.alarm.pending} pending, ${e.alarm.outstanding} outstanding`);
  } else if (e.diagnosis) {
    s.diags += 1;
  } else if (e.dropped) {
    log(`${t}  the stream lost ${e.dropped.count} events (this page read too slowly)`);
  }
  if (selected === null && (s.kind === "rs4" || s.values["rs4-state"] !== undefined)) selected = address;
  scheduleRender();
  if (address === selected) refreshSelected();
  if (gsdStations.has(address)) { refreshGsd(address); return; }
  if (lineOf.get(address)) refreshLine(address);
}

let renderPending = false;
function scheduleRender() {
  if (renderPending) return;
  renderPending = true;
  requestAnimationFrame(() => { renderPending = false; renderStations(); });
}

function select(address) {
  selected = address;
  fieldsFor = null;
  renderStations();
  refreshSelected();
}

// ---- the RS4: contour, fields, obstacles, bits ----------------------------------------------
let fieldsFor = null;  // "address/pair" whose fields are drawn
let fields = { protective: null, warning: null };
let refreshing = false, refreshAgain = false;

// A contour of the parameter document (docs/param.md) as 529 distances; `get` prints runs.
function contourOf(c) {
  const mm = new Array(SEGMENTS).fill(0);
  if (!c) return mm;
  if (c.segments) return c.segments.slice(0, SEGMENTS);
  for (const r of c.runs || []) for (let n = r.from; n <= r.to; n++) mm[n] = r.mm;
  return mm;
}

const point = (n, d) => [d * Math.cos(angle(n)), -d * Math.sin(angle(n))];  // SVG y points down

function fieldPath(mm) {
  let d = "M0 0";
  for (let n = 0; n < SEGMENTS; n++) {
    const [x, y] = point(n, mm[n]);
    d += ` L${x.toFixed(0)} ${y.toFixed(0)}`;
  }
  return d + " Z";
}

async function refreshSelected() {
  if (selected === null) return;
  if (refreshing) { refreshAgain = true; return; }
  refreshing = true;
  try {
    const address = selected;
    const [state, contour] = await Promise.all([
      call("rs4sim.v1.Observation/GetState", { address }),
      call("rs4sim.v1.Observation/GetContour", { address }).catch(() => null),
    ]);
    station(address).state = state;
    const key = address + "/" + state.activeFieldPair;
    if (fieldsFor !== key) {
      fieldsFor = key;
      try {
        const doc = JSON.parse((await call("rs4sim.v1.Device/GetParameterSet", { address })).json);
        const pairs = doc.pairs || {};
        const pair = pairs[String(state.activeFieldPair)] || pairs["1"] || {};
        fields = { protective: contourOf(pair.protective), warning: contourOf(pair.warning) };
      } catch (err) {  // the demo serves Observation only: no fields to draw
        fields = { protective: null, warning: null };
      }
    }
    drawRs4(address, state, contour);
    scheduleRender();
  } catch (err) {
    log("GetState: " + err.message);
  } finally {
    refreshing = false;
    if (refreshAgain) { refreshAgain = false; refreshSelected(); }
  }
}

function drawRs4(address, state, contour) {
  $("rs4-panel").hidden = false;
  $("rs4-address").textContent = address;
  $("rs4-pair").textContent = state.activeFieldPair;
  $("rs4-scan").textContent = contour ? contour.scanNumber : "–";
  const scan = $("scan");
  scan.dataset.address = address;
  scan.dataset.state = state.rs4State;
  scan.dataset.ossd = state.ossd ? "on" : "off";
  const max = Math.max(1000, ...(fields.warning || []), ...(fields.protective || []));
  const r = Math.ceil(max * 1.25 / 500) * 500;  // the view's radius, mm
  scan.setAttribute("viewBox", `${-r} ${-r} ${2 * r} ${r * 1.12}`);
  drawGrid(r);
  $("protective-field").setAttribute("d", fields.protective ? fieldPath(fields.protective) : "");
  $("warning-field").setAttribute("d", fields.warning ? fieldPath(fields.warning) : "");
  const obstacles = $("obstacles");
  obstacles.replaceChildren();
  const pts = [];
  const mm = contour ? contour.mm : [];
  for (let n = 0; n < mm.length; n++) {
    const d = mm[n];
    if (d === NO_ECHO || d > r) continue;
    const [x, y] = point(n, d);
    pts.push(`${x.toFixed(0)},${y.toFixed(0)}`);
    const inP = fields.protective && d < fields.protective[n];
    const inW = !inP && fields.warning && d < fields.warning[n];
    if (inP || inW) {
      obstacles.append(svg("circle", { cx: x.toFixed(0), cy: y.toFixed(0), r: (r / 70).toFixed(0),
        class: "obstacle" + (inP ? "" : " warning"), "data-segment": n, "data-mm": d,
        "data-field": inP ? "protective" : "warning" }));
    }
  }
  $("contour").setAttribute("points", pts.join(" "));
  drawBits("in-bits", "in-hex", state.inputByte, [
    ["warning field", "warningFieldViolated"], ["protective field", "protectiveFieldViolated"],
    ["proxy request", "proxyRequest"], ["RS232 active", "rs232Active"],
    ["not operational", "notOperational"], ["error", "error"],
    ["warning output (0 = active)", null], ["OSSD", "ossd"]]);
  drawBits("out-bits", "out-hex", state.outputByte, [
    ["field pair bit 0", null], ["field pair bit 1", null], ["field pair bit 2", null],
    ["restart", null], ["–", null], ["–", null], ["proxy enable", null], ["–", null]]);
  const kv = $("rs4-kv");
  kv.replaceChildren();
  const rows = [["RS4 state", state.rs4State], ["LED", state.led],
    ["LED3", state.led3Red ? "red" : "off"], ["LED5", state.led5YellowBlinking ? "yellow, blinking" : "off"],
    ["restart button", state.restartButtonHeld ? "held" : "released"], ["PROFIsafe", state.fdeviceState],
    ["proxy phase", state.proxyPhase], ["OSSD", state.ossd ? "on" : "off"],
    ["contamination", state.contaminationPercent + " %"], ["faults", (state.faultsPresent || []).join(", ") || "none"],
    ["PC adapter", state.pcAdapterAttached ? "attached" : "detached"], ["F_Dest_Add", state.fDestAdd]];
  if (state.plc && state.plc.present) rows.push(["PLC reads", "0x" + hex(state.plc.inputByte) + " (" + state.plc.fhostState + ")"]);
  for (const [k, v] of rows) kv.append(Object.assign(el("tr"), { innerHTML: `<td>${k}</td><td>${v}</td>` }));
}

const hex = (b) => Number(b).toString(16).padStart(2, "0").toUpperCase();

function drawBits(table, label, byte, names) {
  $(label).textContent = "0x" + hex(byte);
  const t = $(table);
  t.replaceChildren();
  const head = el("tr"), vals = el("tr"), desc = el("tr");
  for (let bit = 7; bit >= 0; bit--) {
    const on = (byte >> bit) & 1;
    head.append(el("td", { class: "bit" }, String(bit)));
    vals.append(el("td", { class: (on ? "on" : "") + (bit === 7 && table === "in-bits" ? " safety" : ""),
      "data-bit": bit }, String(on)));
    desc.append(el("td", {}, names[bit][0]));
  }
  t.append(head, vals, desc);
}

function drawGrid(r) {
  const g = $("grid"), scale = $("scale");
  g.replaceChildren();
  scale.replaceChildren();
  const step = r > 6000 ? 2000 : r > 2500 ? 1000 : 500;
  const font = (r / 28).toFixed(0);
  for (let d = step; d <= r; d += step) {
    g.append(svg("circle", { r: d }));
    const t = svg("text", { x: 8, y: -d + r / 40, "font-size": font });
    t.textContent = (d / 1000) + " m";
    g.append(t);
  }
  g.append(svg("line", { x1: -r, y1: 0, x2: r, y2: 0 }), svg("line", { x1: 0, y1: 0, x2: 0, y2: -r }));
  // the scale bar: one step, bottom left, in millimetres
  const y = r * 0.08, x = -r * 0.95;
  scale.append(svg("line", { x1: x, y1: y, x2: x + step, y2: y }));
  const t = svg("text", { x: x, y: y - r / 60, "font-size": font });
  t.textContent = step + " mm";
  scale.append(t);
}

// ---- GridScan, METRON, Polaris: their elements/beams ------------------------------------------
// The run's station list (Run.Describe) says which station is which: `station` is its
// rs4sim.v1.StationKind.
const LINE_KINDS = [
  { kind: "gridscan", station: "STATION_KIND_GRIDSCAN", service: "rs4sim.v1.GridScan", count: (st) => st.elements,
    text: (st) => `${st.power || "–"}, ${st.mode || "–"}, ${st.configuration || "–"}` +
      (st.reportInterrupted ? ", reports interrupted" : "") },
  { kind: "metron", station: "STATION_KIND_METRON", service: "rs4sim.v1.Metron", count: (st) => st.beams,
    text: (st) => `OSSD ${st.ossd ? "on" : "off"}, ${st.synchronised ? "synchronised" : "not synchronised"}` +
      (st.interruptedCount ? `, ${st.interruptedCount} interrupted (${st.firstInterrupted}–${st.lastInterrupted})` : "") },
  { kind: "polaris", station: "STATION_KIND_POLARIS", service: "rs4sim.v1.Polaris", count: (st) => st.beams,
    text: (st) => `${st.family || ""} ${st.dataMode || ""}, PN1 ${st.pn1 ? "on" : "off"}, PN2 ${st.pn2 ? "on" : "off"}` },
];
const lineOf = new Map();  // address -> entry of LINE_KINDS (the run's line devices)

// The run's stations, as Run.Describe lists them: their kinds, and the line devices drawn.
function takeStations(list) {
  for (const st of list || []) {
    const address = Number(st.address || 0);
    const gsd = st.kind === "STATION_KIND_GENERIC" && (st.services || []).includes("rs4sim.v1.GsdStations");
    station(address).kind = gsd ? "gsd" : st.name;
    const k = LINE_KINDS.find((line) => line.station === st.kind && served.has(line.service));
    if (k) { lineOf.set(address, k); refreshLine(address); }
  }
  scheduleRender();
}

const lineRefreshing = new Set();
async function refreshLine(address) {
  const k = lineOf.get(address);
  if (!k || lineRefreshing.has(address)) return;
  lineRefreshing.add(address);
  try {
    drawLine(address, k, await call(k.service + "/GetState", { address }));
  } catch (err) {
    log(`${k.kind} GetState: ${err.message}`);
  } finally { lineRefreshing.delete(address); }
}

// One row of cells, element/beam 1 first; data-state free or interrupted (the scene's
// blocked list), every tenth cell marked.
function drawLine(address, k, st) {
  $("lines-panel").hidden = false;
  let box = $("lines").querySelector(`.line-device[data-address="${address}"]`);
  if (!box) {
    box = el("div", { class: "line-device", "data-address": address, "data-kind": k.kind });
    box.append(el("h3"), el("div", { class: "beams" }));
    $("lines").append(box);
  }
  const n = Number(k.count(st) || 0), blocked = new Set((st.blocked || []).map(Number));
  box.dataset.interrupted = blocked.size;
  box.dataset.state = blocked.size ? "interrupted" : "free";
  const h = box.querySelector("h3");
  h.textContent = `${k.kind} at address ${address} `;
  h.append(el("span", { class: "sub" }, `${n} ${k.kind === "gridscan" ? "elements" : "beams"}; ${k.text(st)}`));
  const row = box.querySelector(".beams");
  while (row.children.length > n) row.lastChild.remove();
  while (row.children.length < n) {
    const i = row.children.length + 1;
    row.append(el("span", { class: "beam" + (i % 10 === 0 ? " tick" : ""), "data-beam": i, title: `${i}` }));
  }
  for (const cell of row.children) {
    const state = blocked.has(Number(cell.dataset.beam)) ? "interrupted" : "free";
    if (cell.dataset.state !== state) cell.dataset.state = state;
  }
}

// ---- GSD stations (rs4sim.v1.GsdStations: `run --gsd FILE`, `run --bus FILE`) ----------------
// Each station from ListStations: address, ident, the modules with their input and output bytes
// bit by bit, DP state and online. Redrawn after every event of the station (dp-state, online,
// inputs, outputs, diagnosis items) and polled once a second for the counters; twice a second
// where the run has no event stream.
const gsdStations = new Map();  // address -> the GsdStation as JSON
let gsdServed = false;

async function pollGsd() {
  let list;
  try { list = await call("rs4sim.v1.GsdStations/ListStations"); } catch (err) { return false; }
  gsdServed = true;
  for (const st of list.stations || []) {
    drawGsd(st);
    await refreshGsdF(Number(st.address || 0));
  }
  return true;
}

const gsdRefreshing = new Set();
async function refreshGsd(address) {
  if (gsdRefreshing.has(address)) return;
  gsdRefreshing.add(address);
  try {
    drawGsd(await call("rs4sim.v1.GsdStations/GetStation", { address }));
    await refreshGsdF(address);
  } catch (err) {
    log(`GSD station ${address}: ${err.message}`);
  } finally { gsdRefreshing.delete(address); }
}

// The station's PROFIsafe F-modules (GsdStations.GetFModules, docs/profisafe.md "GSD F-devices"):
// mode, state, the diagnosis with the GSD's (or the standard's) text, F-inputs and F-outputs,
// and our master's F-host where the run has one. Asked once more only for a station that has
// F-modules.
const gsdWithoutF = new Set();
async function refreshGsdF(address) {
  if (gsdWithoutF.has(address)) return;
  let f;
  try { f = await call("rs4sim.v1.GsdStations/GetFModules", { address }); } catch (err) {
    log(`GSD station ${address} F-modules: ${err.message}`);
    return;
  }
  if (!(f.modules || []).length) { gsdWithoutF.add(address); return; }
  drawGsdF(address, f.modules);
}

function drawGsdF(address, modules) {
  const box = $("gsd").querySelector(`.gsd-station[data-address="${address}"]`);
  if (!box) return;
  let list = box.querySelector(".gsd-f");
  if (!list) { list = el("div", { class: "gsd-f" }); box.append(list); }
  list.replaceChildren();
  for (const m of modules) {
    const size = Number(m.fDataLength || 0);
    const inputs = bytesOf(m.fInputs, size), outputs = bytesOf(m.fOutputs, size);
    const state = m.state || "";
    const f = el("div", { class: "gsd-fmodule", "data-slot": Number(m.slot || 0), "data-mode": m.mode,
      "data-state": state, "data-diagnosis": Number(m.diagnosis || 0),
      "data-f-inputs": inputs.map((b) => hex(b).toLowerCase()).join(" "),
      "data-f-outputs": outputs.map((b) => hex(b).toLowerCase()).join(" "),
      "data-host": m.host ? m.host.state : "" });
    const head = el("h4");
    head.append(`F-module slot ${Number(m.slot || 0)} "${m.name}" · PROFIsafe ${m.mode} `);
    head.insertAdjacentHTML("beforeend", pill(state, state === "run" ? "ok" : "bad") +
      (m.host ? " F-host " + pill(m.host.state, m.host.state === "run" ? "ok" : "bad") : ""));
    f.append(head);
    const notes = [`F_Dest_Add ${Number(m.fDestAdd || 0)}`, `number ${Number(m.consecutiveNumber || 0)}`,
      `status ${(m.statusBits || []).join(" ") || "–"}`, `host control ${(m.hostControlBits || []).join(" ") || "–"}`];
    if (m.diagnosis) notes.unshift(`diagnosis ${m.diagnosis}: ${m.diagnosisText}`);
    f.append(el("p", { class: "gsd-fdiag note" }, notes.join(" · ")));
    const io = el("div", { class: "gsd-fio" });
    io.append(el("span", {}, "F-inputs (device → host) "), byteCells(inputs, "in"),
      el("span", {}, m.fOutputsFailSafe ? " F-outputs: fail-safe values " : " F-outputs (host → device) "),
      byteCells(outputs, "out"));
    f.append(io);
    list.append(f);
  }
}

// The JSON mapping's base64 `bytes` as numbers, `length` of them (zeros where none were set).
function bytesOf(b64, length) {
  const raw = atob(b64 || "");
  const out = [];
  for (let i = 0; i < Math.max(length, raw.length); i++) out.push(i < raw.length ? raw.charCodeAt(i) : 0);
  return out;
}

// One byte: its number and hex value over eight cells, bit 7 on the left.
function byteCells(bytes, direction) {
  if (!bytes.length) return el("span", { class: "note" }, "–");
  const box = el("div", { class: "bytes " + direction });
  bytes.forEach((value, i) => {
    const b = el("div", { class: "byte", "data-byte": i, "data-value": hex(value).toLowerCase() });
    b.append(el("div", { class: "byte-label" }, `byte ${i} · 0x${hex(value)}`));
    const cells = el("div", { class: "bitrow" });
    for (let bit = 7; bit >= 0; bit--) {
      const on = (value >> bit) & 1;
      cells.append(el("span", { class: "b" + (on ? " on" : ""), "data-bit": bit,
        title: `byte ${i} bit ${bit}` }, String(on)));
    }
    b.append(cells);
    box.append(b);
  });
  return box;
}

function drawGsd(st) {
  const address = Number(st.address || 0);
  gsdStations.set(address, st);
  const s = station(address);
  if (!s.kind) s.kind = "gsd";
  // the station list's row, also where the run has no event stream (the items' names)
  const all = (key, len) => (st.modules || []).flatMap((m) => bytesOf(m[key], Number(m[len] || 0)));
  Object.assign(s.values, { "dp-state": st.dpState, online: st.online ? "yes" : "no",
    inputs: all("inputs", "inputLength").map((b) => hex(b).toLowerCase()).join(" "),
    outputs: all("outputs", "outputLength").map((b) => hex(b).toLowerCase()).join(" ") });
  $("gsd-panel").hidden = false;
  let box = $("gsd").querySelector(`.gsd-station[data-address="${address}"]`);
  if (!box) {
    box = el("div", { class: "gsd-station", "data-address": address });
    box.append(el("h3"), el("p", { class: "gsd-diag note" }), el("table", { class: "gsd-modules" }));
    $("gsd").append(box);
    [...$("gsd").children].sort((a, b) => a.dataset.address - b.dataset.address)
      .forEach((c) => $("gsd").append(c));
  }
  box.dataset.state = st.dpState || "";
  box.dataset.online = st.online ? "yes" : "no";
  box.dataset.ident = "0x" + Number(st.identNumber || 0).toString(16).padStart(4, "0").toUpperCase();
  const h = box.querySelector("h3");
  const file = (st.file || "").split("/").pop();
  h.innerHTML = "";
  h.append(`Station ${address} `);
  h.insertAdjacentHTML("beforeend", pill(st.dpState, dpClass(st.dpState)) + " " +
    pill(st.online ? "online" : "off the bus", st.online ? "ok" : "bad"));
  h.append(el("span", { class: "sub" }, `ident ${box.dataset.ident} · ${file}` +
    `${st.dpv1 ? " · DPV1" : ""} · ${Number(st.dataExchanges || 0)} data exchanges`));
  const notes = [];
  if (st.prmFault) notes.push("Set_Prm refused: " + st.prmFault);
  if ((st.diagnosisTexts || []).length) notes.push("diagnosis: " + st.diagnosisTexts.join("; "));
  const diag = box.querySelector(".gsd-diag");
  diag.textContent = notes.join(" · ");
  diag.hidden = notes.length === 0;
  const t = box.querySelector("table");
  t.replaceChildren();
  t.append(Object.assign(el("tr"), { innerHTML:
    "<th>Slot</th><th>Module</th><th>Inputs (station → master)</th><th>Outputs (master → station)</th>" }));
  for (const m of st.modules || []) {
    const inputs = bytesOf(m.inputs, Number(m.inputLength || 0));
    const outputs = bytesOf(m.outputs, Number(m.outputLength || 0));
    const row = el("tr", { class: "gsd-module", "data-slot": Number(m.slot || 0),
      "data-inputs": inputs.map((b) => hex(b).toLowerCase()).join(" "),
      "data-outputs": outputs.map((b) => hex(b).toLowerCase()).join(" ") });
    row.append(el("td", {}, String(Number(m.slot || 0))), el("td", { class: "module" }, m.name));
    const i = el("td"), o = el("td");
    i.append(byteCells(inputs, "in"));
    o.append(byteCells(outputs, "out"));
    row.append(i, o);
    t.append(row);
  }
  scheduleRender();
}

// ---- our master's F-hosts for GSD F-devices (`master`: rs4sim.v1.GsdMaster) --------------------
// One row per F-module: its F-host's state, the fault that passivated it, the F-data received
// and sent, and an ACK_REI button while ACK_REQ stands (GsdMaster.AcknowledgeF).
const fHex = (b64) => bytesOf(b64, 0).map((b) => hex(b).toLowerCase()).join(" ") || "–";

async function pollGsdMaster() {
  let list;
  try { list = await call("rs4sim.v1.GsdMaster/ListSlaves"); } catch (err) { return false; }
  for (const slave of list.slaves || []) {
    for (const f of slave.fModules || []) drawFHost(Number(slave.address || 0), f);
  }
  $("gsd-fhost-panel").hidden = $("gsd-fhost").tBodies[0].rows.length === 0;
  return true;
}

// The row of one F-module, made once (its ACK_REI button stays the same element between polls,
// so a click is never lost to a redraw) and filled from the F-host's state.
function drawFHost(address, f) {
  const slot = Number(f.slot || 0);
  const body = $("gsd-fhost").tBodies[0];
  let row = body.querySelector(`tr[data-address="${address}"][data-slot="${slot}"]`);
  if (!row) {
    row = el("tr", { class: "gsd-fhost", "data-address": address, "data-slot": slot });
    for (let i = 0; i < 10; i++) row.append(el("td"));
    const ack = el("button", { class: "ack-rei" }, "ACK_REI");
    ack.addEventListener("click", async () => {
      try {
        await call("rs4sim.v1.GsdMaster/AcknowledgeF", { address, slot });
        log(`GSD slave ${address} slot ${slot}: ACK_REI`);
      } catch (err) { log(`ACK_REI ${address}/${slot}: ${err.message}`); }
      pollGsdMaster();
    });
    const cell = el("td");
    cell.append(ack);
    row.append(cell);
    body.append(row);
  }
  row.dataset.state = f.fState || "";
  const n = (k) => Number((f.counters || {})[k] || 0);
  const cells = row.cells;
  cells[0].textContent = String(address);
  cells[1].textContent = String(slot);
  cells[2].textContent = f.mode || "–";
  cells[3].innerHTML = pill(f.fState, fClass(f.fState));
  cells[4].textContent = f.passivated ? "yes" : "no";
  cells[5].innerHTML = f.ackReq ? pill("ACK_REQ", "warn") : "–";
  cells[6].textContent = f.lastFault || "–";
  cells[7].textContent = fHex(f.fInputs);
  cells[8].textContent = fHex(f.fOutputsSent);
  cells[9].textContent = `${n("crc_errors")} / ${n("number_errors")} / ${n("watchdog_timeouts")} / ${n("passivations")}`;
  row.querySelector(".ack-rei").disabled = !f.ackReq;
}

// ---- simulated time -------------------------------------------------------------------------
// Read at the start and, on the simulated clock, four times a second: whoever moves the time
// (a script over the API, another page) moves this clock too. True when the run is simulated.
async function refreshClock(t) {
  try {
    const now = t || await call("rs4sim.v1.SimTime/Now");
    if (now.startNs !== undefined) clockStart = Number(now.startNs);
    simulatedRun = Boolean(now.simulated);
    if (!now.simulated) return false;
    $("clock").hidden = false;
    $("clock-now").textContent = sinceStart(now.nowNs);
    return true;
  } catch (err) { log("SimTime: " + err.message); return false; }
}
for (const b of document.querySelectorAll("#clock button")) {
  b.addEventListener("click", async () => {
    try {
      await refreshClock(await call("rs4sim.v1.SimTime/Advance", { durationMs: Number(b.dataset.advance) }));
      refreshSelected();
    } catch (err) { log("Advance: " + err.message); }
  });
}

// ---- the parameter archive (`master --archive`: rs4sim.v1.Archive) ---------------------------
let archiveKey = null;    // {bus, address} whose history is shown
let archiveDiffed = "";   // "old/new" drawn last
let archiveVersion = null; // the version row clicked (diffed against its predecessor)

const keyText = (k) => `${k.bus || "default"}/${k.address || 0}`;

async function pollArchive() {
  let list;
  try { list = await call("rs4sim.v1.Archive/ListStations"); } catch (err) { return false; }
  $("archive-panel").hidden = false;
  $("archive-name").textContent = list.archive || "(not named)";
  const body = $("archive-stations").tBodies[0];
  body.replaceChildren();
  for (const st of list.stations || []) {
    const k = st.key || {};
    if (!archiveKey) archiveKey = { bus: k.bus || "", address: k.address || 0 };
    const row = el("tr", { class: "archive-station", "data-address": k.address || 0,
      "data-bus": k.bus || "default", "data-current": st.currentVersionId });
    row.classList.toggle("selected", keyText(k) === keyText(archiveKey));
    row.innerHTML = `<td>${keyText(k)}</td><td>${st.deviceType}</td>` +
      `<td>${(st.serialNumbers || []).join(", ")}</td><td>${st.currentVersionId}</td>` +
      `<td>${[st.site, st.line].filter(Boolean).join(" / ") || "–"}</td>`;
    row.addEventListener("click", () => {
      archiveKey = { bus: k.bus || "", address: k.address || 0 };
      archiveVersion = null;
      pollArchive();
    });
    body.append(row);
  }
  if (archiveKey) await showHistory(archiveKey);
  return true;
}

async function showHistory(key) {
  const history = await call("rs4sim.v1.Archive/History", key).catch(() => ({ versions: [] }));
  const versions = history.versions || [];
  $("archive-station").textContent = keyText(key);
  const body = $("archive-history").tBodies[0];
  body.replaceChildren();
  for (const v of versions) {
    const row = el("tr", { class: "version", "data-address": key.address, "data-version": v.id,
      "data-source": v.source });
    row.classList.toggle("selected", String(v.id) === String(archiveVersion));
    const at = new Date(Number(v.storedAtMs)).toISOString().replace("T", " ").slice(0, 19);
    row.innerHTML = `<td>${v.id}</td><td>${v.number}</td><td>${v.source}${v.pendingDownload ? " (pending)" : ""}</td>` +
      `<td>${at} UTC</td><td>${[v.user, v.host].filter(Boolean).join("@") || "–"}</td>` +
      `<td><code>${hex8(v.crc32)}</code></td><td>${v.note || ""}</td>`;
    row.addEventListener("click", () => { archiveVersion = v.id; showHistory(key); });
    body.append(row);
  }
  // The picked version against the one before it; else the newest two.
  const ids = versions.map((v) => String(v.id));
  let at = archiveVersion === null ? ids.length - 1 : ids.indexOf(String(archiveVersion));
  if (at < 1) at = ids.length - 1;
  if (ids.length < 2) {
    $("archive-diff-title").textContent = ids.length ? "(one version: nothing to compare)" : "";
    $("archive-diff").replaceChildren();
    $("archive-diff-text").textContent = "";
    archiveDiffed = "";
    return;
  }
  const pair = ids[at - 1] + "/" + ids[at];
  if (pair === archiveDiffed) return;
  const d = await call("rs4sim.v1.Archive/Diff",
    { oldVersionId: ids[at - 1], newVersionId: ids[at], withSvg: true });
  archiveDiffed = pair;
  $("archive-diff-title").textContent = `version ${ids[at - 1]} → ${ids[at]}` +
    (d.identical ? " (identical sets)" : "");
  $("archive-diff-text").textContent = d.text;
  const box = $("archive-diff");
  box.dataset.address = key.address;
  box.dataset.old = ids[at - 1];
  box.dataset.new = ids[at];
  box.dataset.identical = d.identical ? "true" : "false";
  box.innerHTML = d.svg;  // our own server's picture, every text in it XML-escaped
}

const hex8 = (n) => Number(n).toString(16).padStart(8, "0").toUpperCase();

// ---- start ------------------------------------------------------------------------------------
async function start() {
  try {
    const run = await call("rs4sim.v1.Run/Describe");
    served = new Set(run.services || []);
    takeStations(run.stations);
  } catch (err) { log("Run.Describe: " + err.message); }
  if (serves("SimTime") && await refreshClock()) setInterval(refreshClock, 250);
  if (serves("Proxy") && await pollProxy()) setInterval(pollProxy, 500);
  let polled = false;
  if (serves("BusMaster") && await pollMaster()) { polled = true; setInterval(pollMaster, 500); }
  if (serves("Archive") && await pollArchive()) { polled = true; setInterval(pollArchive, 2000); }
  if (serves("GsdMaster") && await pollGsdMaster()) { polled = true; setInterval(pollGsdMaster, 500); }
  const gsd = serves("GsdStations") && await pollGsd();
  let gsdPoll = gsd ? setInterval(pollGsd, 1000) : null;
  if (!serves("Observation")) {
    // No event source in this run (`master`): the page polls what it serves.
    if (gsd) { polled = true; clearInterval(gsdPoll); gsdPoll = setInterval(pollGsd, 500); }
    $("link").dataset.state = polled ? "polling" : "lost";
    $("link").textContent = polled ? "polling" : "no event stream";
    return;
  }
  const events = new EventSource("/api/events" + (token ? "?access_token=" + encodeURIComponent(token) : ""));
  events.onopen = () => { $("link").dataset.state = "live"; $("link").textContent = "live"; };
  events.onerror = () => {
    // A run without an event source (`master`) refuses the stream: the page polls instead.
    const closed = events.readyState === EventSource.CLOSED;
    if (closed && gsd) { polled = true; clearInterval(gsdPoll); gsdPoll = setInterval(pollGsd, 500); }
    $("link").dataset.state = closed && polled ? "polling" : "lost";
    $("link").textContent = closed ? (polled ? "polling" : "no event stream") : "reconnecting…";
  };
  events.onmessage = (m) => onEvent(JSON.parse(m.data));
  events.addEventListener("end", () => { $("link").dataset.state = "lost"; $("link").textContent = "run ended"; events.close(); });
  // The contour moves without an event: the selected RS4 is read four times a second.
  setInterval(refreshSelected, 250);
  setInterval(() => { for (const a of lineOf.keys()) refreshLine(a); }, 250);
}
start();
