// flexshaft explore: the page. Plain JavaScript, no framework; every request goes to this server.
"use strict";

const state = {
  session: (self.crypto && crypto.randomUUID) ? crypto.randomUUID() : String(Math.random()).slice(2),
  base: "file",
  overrides: {},
  advanced: {},
  controls: [],
  seq: 0,
  shown: -1,
  summary: "",
  lastSent: {},
};
const $ = (id) => document.getElementById(id);
const PLOT_CONFIG = {responsive: true, displaylogo: false};

async function api(path, body) {
  const options = body === undefined ? {} : {
    method: "POST", headers: {"Content-Type": "application/json"}, body: JSON.stringify(body),
  };
  const response = await fetch(path, options);
  const data = await response.json();
  return {ok: response.ok, status: response.status, data};
}

function shown(value) {
  if (value === null || value === undefined || !isFinite(value)) return "";
  return String(Number(Number(value).toPrecision(6)));
}

function esc(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"}[c]));
}

// ---------------------------------------------------------------------------------------------
// Controls

function buildControls(controls) {
  state.controls = controls;
  const box = $("controls");
  box.innerHTML = "";
  const groups = new Map();
  for (const c of controls) {
    if (!groups.has(c.group)) {
      const fieldset = document.createElement("fieldset");
      fieldset.innerHTML = `<legend>${esc(c.group)}</legend>`;
      groups.set(c.group, fieldset);
      box.appendChild(fieldset);
    }
    const row = document.createElement("div");
    row.className = "control";
    row.title = c.help;
    const limits = [];
    if (c.minimum !== null) limits.push(`${c.exclusive_minimum ? ">" : "≥"} ${shown(c.minimum)}`);
    if (c.maximum !== null) limits.push(`${c.exclusive_maximum ? "<" : "≤"} ${shown(c.maximum)}`);
    const id = "ctl-" + c.key;
    row.innerHTML =
      `<label for="${esc(id)}">${esc(c.label)}</label>` +
      `<input id="${esc(id)}" type="number" step="any" data-key="${esc(c.key)}"` +
      (c.minimum !== null ? ` min="${c.minimum}"` : "") + (c.maximum !== null ? ` max="${c.maximum}"` : "") +
      ` title="${esc(limits.join(", "))}">` +
      `<span class="muted">${esc(c.unit)}</span>` +
      `<div class="problem" id="${esc("err-" + c.key)}" role="alert"></div>`;
    groups.get(c.group).appendChild(row);
    const input = row.querySelector("input");
    input.value = shown(c.value);
    state.lastSent[c.key] = input.value;
    input.addEventListener("change", () => edit(c.key, input));
    input.addEventListener("keydown", (event) => step(event, c, input));
  }
  const select = $("sweep-control");
  const previous = select.value;
  select.innerHTML = controls.map((c) => `<option value="${esc(c.key)}">${esc(c.group + ": " + c.label + " [" + c.unit + "]")}</option>`).join("");
  if (controls.some((c) => c.key === previous)) select.value = previous;
  sweepDefaults();
}

function refreshControls(controls) {
  const same = controls.length === state.controls.length && controls.every((c, i) => c.key === state.controls[i].key);
  if (!same) { buildControls(controls); return; }
  state.controls = controls;
  for (const c of controls) {
    const input = $("ctl-" + c.key);
    input.value = shown(c.value);
    input.classList.remove("invalid");
    state.lastSent[c.key] = input.value;
    $("err-" + c.key).textContent = "";
  }
}

function step(event, control, input) {
  if (event.key !== "ArrowUp" && event.key !== "ArrowDown") return;
  event.preventDefault();
  const value = Number(input.value);
  if (!isFinite(value)) return;
  const up = event.key === "ArrowUp";
  let next;
  if (control.log) next = value === 0 ? (up ? 1 : 0) : (up ? value * control.step : value / control.step);
  else next = up ? value + control.step : value - control.step;
  input.value = shown(next);
  edit(control.key, input);
}

function edit(key, input) {
  if (input.value === state.lastSent[key]) return;
  state.lastSent[key] = input.value;
  input.classList.add("changed");
  const value = input.value.trim() === "" ? NaN : Number(input.value);
  if (!isFinite(value)) {
    showProblems([{path: key, message: `expected a number, got "${input.value}"`}], key, state.seq + 0.5);
    return;
  }
  update({[key]: value}, {}, key);
}

// ---------------------------------------------------------------------------------------------
// Updates

function clearProblems() {
  for (const el of document.querySelectorAll(".problem")) el.textContent = "";
  for (const el of document.querySelectorAll(".control input.invalid")) el.classList.remove("invalid");
}

function controlOf(path) {
  return state.controls.find((c) => c.key === path || c.paths.some((p) => path === p || path.startsWith(p + ".") || path.startsWith(p + "[")));
}

// The problems of the newest refused request: an older update that answers after it must not
// clear them (its design is still the last valid one, but the refused value stays on show).
function showProblems(problems, editedKey, seq) {
  const typed = {};
  clearProblems();
  for (const p of problems) {
    const text = `${p.path}: ${p.message}`;
    const control = controlOf(p.path) || (editedKey && state.controls.find((c) => c.key === editedKey));
    if (control) {
      const box = $("err-" + control.key);
      box.textContent = box.textContent ? box.textContent + "\n" + text : text;
      $("ctl-" + control.key).classList.add("invalid");
      typed[control.key] = $("ctl-" + control.key).value;
    } else if (editedKey === "advanced") {
      $("advanced-error").textContent += ($("advanced-error").textContent ? "\n" : "") + text;
    } else {
      $("general-error").textContent += ($("general-error").textContent ? "\n" : "") + text;
    }
  }
  state.refused = {seq, problems, editedKey, typed};
}

function keepRefused(seq) {
  const refused = state.refused;
  if (!refused || refused.seq < seq) { state.refused = null; return; }
  for (const [key, value] of Object.entries(refused.typed)) {
    const input = $("ctl-" + key);
    if (input) { input.value = value; state.lastSent[key] = value; }
  }
  showProblems(refused.problems, refused.editedKey, refused.seq);
}

async function update(edits, advanced, editedKey) {
  const seq = ++state.seq;
  const started = performance.now();
  $("busy").hidden = false;
  const {ok, data} = await api("/api/update", {
    session: state.session, seq, base: state.base, overrides: state.overrides, edits, advanced,
  });
  if (seq === state.seq) $("busy").hidden = true;
  if (!ok) {
    if (seq === state.seq) showProblems(data.problems || [{path: "request", message: data.message || "refused"}], editedKey, seq);
    return;
  }
  if (data.superseded || seq < state.shown) return;
  state.shown = seq;
  state.overrides = data.overrides;
  if (editedKey === "advanced") state.advanced = {...state.advanced, ...advanced};
  clearProblems();
  refreshControls(data.controls);
  render(data.results);
  keepRefused(seq);
  const roundTrip = (performance.now() - started) / 1000;
  $("update-time").textContent =
    `update ${roundTrip.toFixed(2)} s (server ${data.server_s.toFixed(2)} s, assessment CPU ${data.results.cpu_s.toFixed(2)} s)`;
  document.body.dataset.seq = String(seq);
  document.body.dataset.roundTrip = String(roundTrip);
  document.body.dataset.serverSeconds = String(data.server_s);
  $("run-command").textContent = "";
  listAdvanced();
}

function render(results) {
  state.summary = results.summary;
  $("design-name").textContent = results.design_name;
  const badge = $("verdict-status");
  badge.textContent = results.passed ? "PASS" : "FAIL";
  badge.className = "badge " + (results.passed ? "pass" : "fail");
  badge.title = results.summary;
  const head = $("verdict-table").querySelector("thead");
  head.innerHTML = "<tr>" + results.columns.map((c) => `<th>${esc(c)}</th>`).join("") + "<th>normalised margin</th></tr>";
  const body = $("verdict-table").querySelector("tbody");
  body.innerHTML = results.checks.map((check) => {
    const cells = results.columns.map((c) => `<td class="${c === "status" ? "status" : ""}">${esc(check.cells[c] || "")}</td>`);
    const margin = check.normalised_margin === null ? "—" : check.normalised_margin.toPrecision(3);
    return `<tr class="${check.status.replace(" ", "-")}" data-key="${esc(check.key)}" data-status="${esc(check.status)}">${cells.join("")}<td>${margin}</td></tr>`;
  }).join("");
  const n = results.numbers;
  const masses = Object.entries(n.mass_by_part_kg).map(([k, v]) => `${esc(k)} ${v.toFixed(1)}`).join(", ");
  $("numbers").innerHTML =
    `<span>shaft mass <b id="shaft-mass">${n.shaft_mass_kg.toFixed(2)}</b> kg</span>` +
    `<span>driveline <b>${n.driveline_mass_kg.toFixed(1)}</b> kg (${masses})</span>` +
    `<span>smallest whirl log decrement <b id="log-decrement">${n.min_log_decrement === null ? "—" : n.min_log_decrement.toPrecision(3)}</b></span>` +
    `<span>whirl onset <b>${n.whirl_onset_rpm === null ? "none to " + n.stable_to_rpm.toFixed(0) : n.whirl_onset_rpm.toFixed(0)}</b> rpm</span>`;
  for (const name of ["margins", "campbell", "spinup", "actuators", "stability"]) {
    const div = $("fig-" + name);
    const figure = results.figures[name];
    if (!figure) { div.hidden = true; continue; }
    div.hidden = false;
    Plotly.react(div, figure.data, figure.layout, PLOT_CONFIG);
  }
}

// ---------------------------------------------------------------------------------------------
// Advanced keys, export, load, reset

function listAdvanced() {
  $("advanced-list").innerHTML = Object.keys(state.overrides).sort()
    .map((path) => `<li><code>${esc(path)} = ${esc(JSON.stringify(state.overrides[path]))}</code></li>`).join("");
}

$("advanced-apply").addEventListener("click", () => {
  const path = $("advanced-path").value.trim();
  const value = $("advanced-value").value.trim();
  $("advanced-error").textContent = "";
  if (!path || !value) { $("advanced-error").textContent = "give a design path and a value"; return; }
  update({}, {[path]: value}, "advanced");
});

$("download").addEventListener("click", async () => {
  const {ok, data} = await api("/api/export", {base: state.base, overrides: state.overrides, verdict: state.summary});
  if (!ok) { showProblems(data.problems || [], null, state.seq); return; }
  const blob = new Blob([data.text], {type: "application/toml"});
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = data.filename;
  document.body.appendChild(link);
  link.click();
  link.remove();
  $("run-command").textContent = data.command;
});

$("copy-command").addEventListener("click", async () => {
  const {ok, data} = await api("/api/export", {base: state.base, overrides: state.overrides, verdict: state.summary});
  if (!ok) return;
  $("run-command").textContent = data.command + "\n# after saving the design with Download design (TOML) as " + data.filename;
  try { await navigator.clipboard.writeText(data.command); } catch (error) { /* shown on the page to copy */ }
});

$("reset").addEventListener("click", () => {
  state.overrides = {};
  state.advanced = {};
  update({}, {}, null);
});

$("load-file").addEventListener("change", async (event) => {
  const file = event.target.files[0];
  if (!file) return;
  $("load-error").textContent = "";
  const text = await file.text();
  const {ok, data} = await api("/api/load", {filename: file.name, text});
  event.target.value = "";
  if (!ok) {
    $("load-error").textContent = (data.problems || []).map((p) => `${p.path}: ${p.message}`).join("\n");
    return;
  }
  state.base = data.base;
  state.overrides = {};
  buildControls(data.controls);
  await update({}, {}, null);
});

// ---------------------------------------------------------------------------------------------
// Full run

$("full-run").addEventListener("click", async () => {
  const box = $("run-status");
  const {ok, data} = await api("/api/run", {base: state.base, overrides: state.overrides});
  if (!ok) { box.textContent = data.error || (data.problems || []).map((p) => p.message).join("\n"); return; }
  const shownVerdict = {};
  for (const row of document.querySelectorAll("#verdict-table tbody tr")) shownVerdict[row.dataset.key] = row.dataset.status;
  box.innerHTML = `<p>full run ${esc(data.job)} into <code>${esc(data.folder)}</code>…</p><ol id="run-steps"></ol>`;
  const poll = async () => {
    const status = (await api(`/api/run/${data.job}`)).data;
    $("run-steps").innerHTML = status.steps.map((s) => `<li>${esc(s.label)} <span class="muted">${s.seconds.toFixed(1)} s</span></li>`).join("");
    if (status.state === "running") { setTimeout(poll, 400); return; }
    if (status.state === "failed") { box.insertAdjacentHTML("beforeend", `<p class="problem">${esc(status.error)}</p>`); return; }
    const r = status.result;
    const differ = Object.keys(r.status).filter((k) => shownVerdict[k] !== undefined && shownVerdict[k] !== r.status[k]);
    box.insertAdjacentHTML("beforeend",
      `<p id="full-run-verdict" data-passed="${r.passed}">full resolution: <b>${r.passed ? "PASS" : "FAIL"}</b> in ${r.seconds.toFixed(1)} s: ${esc(r.summary)}` +
      (differ.length ? `<br><span class="problem">differs from the screening verdict: ${esc(differ.join(", "))}</span>` : "") +
      `<br><a href="/runs/${data.job}/report.html" target="_blank">report.html</a> · ` +
      `<a href="/runs/${data.job}/interactive.html" target="_blank">interactive.html</a></p>`);
  };
  poll();
});

// ---------------------------------------------------------------------------------------------
// Sweep

function sweepDefaults() {
  const control = state.controls.find((c) => c.key === $("sweep-control").value) || state.controls[0];
  if (!control) return;
  let low = control.log ? control.value / 3 : control.value * 0.7;
  let high = control.log ? control.value * 3 : control.value * 1.3;
  if (control.value === 0) { low = 0; high = 30; }
  if (control.minimum !== null) low = Math.max(low, control.minimum);
  if (control.maximum !== null) high = Math.min(high, control.maximum);
  $("sweep-from").value = shown(low);
  $("sweep-to").value = shown(high);
}
$("sweep-control").addEventListener("change", sweepDefaults);

$("sweep-run").addEventListener("click", async () => {
  const key = $("sweep-control").value;
  const control = state.controls.find((c) => c.key === key);
  const low = Number($("sweep-from").value), high = Number($("sweep-to").value);
  const n = Math.max(2, Math.min(41, Math.round(Number($("sweep-points").value) || 9)));
  const values = [];
  for (let i = 0; i < n; i++) {
    const t = i / (n - 1);
    values.push(control.log && low > 0 && high > 0 ? low * Math.pow(high / low, t) : low + (high - low) * t);
  }
  $("sweep-status").textContent = `sweeping ${n} points…`;
  const {ok, data} = await api("/api/sweep", {base: state.base, overrides: state.overrides, control: key, values});
  if (!ok) { $("sweep-status").textContent = (data.problems || []).map((p) => `${p.path}: ${p.message}`).join("; "); return; }
  const titles = {};
  for (const p of data.points) if (p.titles) Object.assign(titles, p.titles);
  const traces = Object.keys(titles).map((checkKey) => ({
    type: "scatter", mode: "lines+markers", name: titles[checkKey], x: values,
    y: data.points.map((p) => (p.margins ? p.margins[checkKey] : null)),
    hovertemplate: `${titles[checkKey]}: %{y:.3g} at %{x:.4g}<extra></extra>`,
  }));
  const invalid = data.points.map((p, i) => (p.error ? i : -1)).filter((i) => i >= 0);
  const layout = {
    title: {text: `Normalised margin of every check against ${control.label} [${control.unit}]`, font: {size: 14}},
    xaxis: {title: {text: `${control.label} [${control.unit}]`}, type: control.log ? "log" : "linear"},
    yaxis: {title: {text: "normalised margin [-] (< 0 fails; above 2 off scale: zoom out)"}, range: [-1, 2]},
    shapes: [
      {type: "line", xref: "paper", x0: 0, x1: 1, y0: 0, y1: 0, line: {color: "#c62828", width: 1.5}},
      {type: "line", yref: "paper", x0: control.value, x1: control.value, y0: 0, y1: 1, line: {color: "#444", dash: "dash"}},
    ],
    margin: {l: 60, r: 16, t: 40, b: 48}, legend: {orientation: "h", y: -0.25}, hovermode: "x unified",
  };
  Plotly.react($("fig-sweep"), traces, layout, PLOT_CONFIG);
  $("sweep-status").textContent = `${n} points in ${data.seconds.toFixed(1)} s` +
    (invalid.length ? `; invalid at ${invalid.map((i) => shown(values[i])).join(", ")}: ${data.points[invalid[0]].error}` : "");
});

// ---------------------------------------------------------------------------------------------
// Pareto front

function drawFront(front) {
  $("pareto-panel").hidden = false;
  const ev = front.evaluations;
  const feasibleX = [], feasibleY = [], otherX = [], otherY = [];
  ev.x.forEach((x, i) => (ev.feasible[i] ? (feasibleX.push(x), feasibleY.push(ev.y[i])) : (otherX.push(x), otherY.push(ev.y[i]))));
  const traces = [
    {type: "scatter", mode: "markers", name: "infeasible", x: otherX, y: otherY, marker: {color: "#bbb", symbol: "x"}, hoverinfo: "skip"},
    {type: "scatter", mode: "markers", name: "feasible", x: feasibleX, y: feasibleY, marker: {color: "#90caf9"}, hoverinfo: "skip"},
    {type: "scatter", mode: "lines+markers", name: "Pareto front (click to load)", x: front.pareto.x, y: front.pareto.y,
     marker: {color: "#0b5394", size: 11}, customdata: front.pareto.overrides.map((o) => JSON.stringify(o)),
     hovertemplate: "%{x:.4g}, %{y:.4g}<br>%{customdata}<extra>Pareto point %{pointNumber}</extra>"},
  ];
  const layout = {
    title: {text: front.name, font: {size: 13}}, xaxis: {title: {text: front.x_label}}, yaxis: {title: {text: front.y_label}},
    margin: {l: 60, r: 16, t: 40, b: 48}, hovermode: "closest",
  };
  const div = $("fig-pareto");
  Plotly.newPlot(div, traces, layout, PLOT_CONFIG);
  div.on("plotly_click", async (event) => {
    const point = event.points.find((p) => p.curveNumber === 2);
    if (point) await loadParetoPoint(point.pointNumber);
  });
}

async function loadParetoPoint(index) {
  const {ok, data} = await api("/api/pareto", {index});
  if (!ok) { $("general-error").textContent = (data.problems || []).map((p) => p.message).join("\n"); return; }
  state.base = data.base;
  state.overrides = data.overrides;
  buildControls(data.controls);
  await update({}, {}, null);
}

// ---------------------------------------------------------------------------------------------

async function start() {
  const {data} = await api("/api/init");
  buildControls(data.controls);
  if (data.front) drawFront(data.front);
  document.body.dataset.ready = "1";
  await update({}, {}, null);
}

window.flexshaftExplore = {state, loadParetoPoint};
start();
