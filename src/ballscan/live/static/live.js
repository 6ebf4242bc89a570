// ballscan's live page: plain JavaScript and canvas, no libraries.
// The server sends numbers in SI units (m/s, s, degrees), each ball's crop as
// 8-bit grey pixels and the fitted silhouette's outline; everything is drawn here.
"use strict";

const TABLE_ROWS_LIVE = 20;   // the live table shows the last N balls
const KEEP_BALLS = 1000;      // balls kept by the page (the server's ring is the same size)
const OKABE_BLUE = "#56B4E9"; // the overlay plot's estimate colour

const state = { mode: "live", units: { "m/s": 1 }, flags: {}, unit: "m/s", balls: [], shown: null, health: null };
const $ = (id) => document.getElementById(id);

function fmt(v, digits) { return v === null || v === undefined ? "–" : v.toFixed(digits); }
function pm(v, s, digits) { return v === null || v === undefined ? "undetermined" : fmt(v, digits) + (s === null || s === undefined ? "" : " ± " + fmt(s, digits)); }
function speed(v) { return v === null || v === undefined ? null : v * state.units[state.unit]; }

// ------------------------------------------------------------------ last ball
function renderLast(ball) {
  state.shown = ball;
  if (!ball) return;
  $("last-index").textContent = "#" + ball.index;
  $("speed").textContent = ball.speed_mps === null ? "undetermined" : fmt(speed(ball.speed_mps), 2);
  $("speed-sigma").textContent = ball.speed_sigma_mps === null ? "" : "± " + fmt(speed(ball.speed_sigma_mps), 2);
  $("speed-transverse").textContent = fmt(speed(ball.speed_transverse_mps), 2);
  $("psi-y").textContent = pm(ball.direction_deg[0], ball.direction_sigma_deg[0], 1) + "°";
  $("psi-z").textContent = pm(ball.direction_deg[1], ball.direction_sigma_deg[1], 1) + "°";
  const flags = $("flags");
  flags.replaceChildren(...ball.flag_text.map((t) => { const li = document.createElement("li"); li.textContent = t; return li; }));
  drawCrop(ball.crop === undefined ? null : ball.crop);
}

function drawCrop(crop) {
  const canvas = $("crop"), ctx = canvas.getContext("2d");
  ctx.fillStyle = "#000";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  if (!crop) { $("crop-note").textContent = "no crop kept for this ball"; return; }
  const bytes = Uint8Array.from(atob(crop.pixels), (c) => c.charCodeAt(0));
  const img = new ImageData(crop.width, crop.height);
  for (let i = 0; i < bytes.length; i++) {
    img.data[4 * i] = img.data[4 * i + 1] = img.data[4 * i + 2] = bytes[i];
    img.data[4 * i + 3] = 255;
  }
  const off = document.createElement("canvas");
  off.width = crop.width; off.height = crop.height;
  off.getContext("2d").putImageData(img, 0, 0);
  // time (lines) downwards, the sensor across, stretched to the canvas as --plot does
  const sx = canvas.width / crop.width, sy = canvas.height / crop.height;
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(off, 0, 0, canvas.width, canvas.height);
  if (crop.outline.length) {
    ctx.strokeStyle = OKABE_BLUE; ctx.lineWidth = 1.5;
    ctx.beginPath();
    crop.outline.forEach(([x, y], k) => {
      const px = (x + 0.5) * sx, py = (y + 0.5) * sy;
      if (k === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    });
    ctx.stroke();
  }
  $("crop-note").textContent = `lines ${crop.first_line}–${crop.first_line + crop.height * crop.step_lines - 1}, ` +
    `pixels ${crop.first_column}–${crop.first_column + crop.width * crop.step_columns - 1}` +
    (crop.outline.length ? "; blue: the fitted silhouette" : "");
}

// ---------------------------------------------------------------------- table
function renderTable() {
  const rows = state.mode === "live" ? state.balls.slice(-TABLE_ROWS_LIVE).reverse() : state.balls;
  const body = $("balls-table").tBodies[0];
  body.replaceChildren(...rows.map((b) => {
    const tr = document.createElement("tr");
    tr.dataset.index = b.index;
    if (b.flags.length) tr.classList.add("flagged");
    if (state.shown && state.shown.index === b.index) tr.classList.add("selected");
    const cells = [b.index, `${b.first_line ?? "–"}–${b.last_line ?? "–"}`, pm(speed(b.speed_mps), speed(b.speed_sigma_mps), 2),
      fmt(speed(b.speed_transverse_mps), 2), pm(b.direction_deg[0], b.direction_sigma_deg[0], 1),
      pm(b.direction_deg[1], b.direction_sigma_deg[1], 1), b.flags.join(" "), b.lag_s === null ? "–" : fmt(1e3 * b.lag_s, 1)];
    cells.forEach((c, k) => {
      const td = document.createElement("td");
      td.textContent = c;
      if (k === 6) { td.className = "flags"; td.title = b.flag_text.join("; "); }
      tr.appendChild(td);
    });
    tr.addEventListener("click", () => showBall(b.index));
    return tr;
  }));
  $("table-note").textContent = state.mode === "live"
    ? `(the last ${rows.length} of ${state.balls.length})` : `(${rows.length} listed)`;
  $("ball-count").textContent = state.mode === "live" && state.health ? state.health.balls : state.balls.length;
}

async function showBall(index) {
  const r = await fetch(`/api/ball/${index}`);
  if (r.ok) { renderLast(await r.json()); renderTable(); }
}

// --------------------------------------------------------------------- charts
function axes(ctx, w, h, pad, xlo, xhi, ylo, yhi, xlabel, ylabel) {
  ctx.clearRect(0, 0, w, h);
  ctx.strokeStyle = "#999"; ctx.fillStyle = "#444"; ctx.font = "11px sans-serif";
  ctx.strokeRect(pad.l, pad.t, w - pad.l - pad.r, h - pad.t - pad.b);
  ctx.fillText(fmt(yhi, 1), 2, pad.t + 9); ctx.fillText(fmt(ylo, 1), 2, h - pad.b);
  ctx.fillText(xlabel, pad.l, h - 4); ctx.fillText(ylabel, pad.l + 4, pad.t + 11);
  ctx.textAlign = "right"; ctx.fillText(`${fmt(xlo, 3)} … ${fmt(xhi, 3)}`, w - pad.r, h - 4); ctx.textAlign = "left";
  const X = (x) => pad.l + (xhi > xlo ? (x - xlo) / (xhi - xlo) : 0.5) * (w - pad.l - pad.r);
  const Y = (y) => h - pad.b - (yhi > ylo ? (y - ylo) / (yhi - ylo) : 0.5) * (h - pad.t - pad.b);
  return [X, Y];
}

function measured() { return state.balls.filter((b) => b.speed_mps !== null); }

function renderChart() {
  const canvas = $("chart"), ctx = canvas.getContext("2d");
  const balls = measured();
  const oneSource = new Set(balls.map((b) => b.source)).size <= 1 && balls.every((b) => b.t_c_s !== null);
  const xs = balls.map((b) => (oneSource ? b.t_c_s : b.index));
  const ys = balls.map((b) => speed(b.speed_mps)), ss = balls.map((b) => speed(b.speed_sigma_mps) || 0);
  const lo = Math.min(...ys.map((y, k) => y - ss[k])), hi = Math.max(...ys.map((y, k) => y + ss[k]));
  const [X, Y] = axes(ctx, canvas.width, canvas.height, { l: 40, r: 8, t: 6, b: 18 },
    xs.length ? Math.min(...xs) : 0, xs.length ? Math.max(...xs) : 1, balls.length ? lo : 0, balls.length ? hi : 1,
    oneSource ? "stream time (s)" : "ball", state.unit);
  ctx.strokeStyle = OKABE_BLUE; ctx.fillStyle = "#0072B2";
  balls.forEach((b, k) => {
    ctx.beginPath(); ctx.moveTo(X(xs[k]), Y(ys[k] - ss[k])); ctx.lineTo(X(xs[k]), Y(ys[k] + ss[k])); ctx.stroke();
    ctx.beginPath(); ctx.arc(X(xs[k]), Y(ys[k]), 2.5, 0, 2 * Math.PI); ctx.fill();
  });
}

function renderHistogram() {
  const canvas = $("histogram"), ctx = canvas.getContext("2d");
  const ys = measured().map((b) => speed(b.speed_mps));
  const n = Math.min(30, Math.max(5, Math.ceil(Math.sqrt(ys.length))));
  const lo = ys.length ? Math.min(...ys) : 0, hi = ys.length ? Math.max(...ys) : 1;
  const width = hi > lo ? (hi - lo) / n : 1;
  const counts = new Array(n).fill(0);
  ys.forEach((y) => { counts[Math.min(n - 1, Math.floor((y - lo) / width))] += 1; });
  const [X, Y] = axes(ctx, canvas.width, canvas.height, { l: 40, r: 8, t: 6, b: 18 },
    lo, hi > lo ? hi : lo + 1, 0, Math.max(1, ...counts), state.unit, "balls");
  ctx.fillStyle = OKABE_BLUE;
  counts.forEach((c, k) => {
    const x0 = X(lo + k * width), x1 = X(lo + (k + 1) * width);
    ctx.fillRect(x0 + 1, Y(c), Math.max(1, x1 - x0 - 2), Y(0) - Y(c));
  });
}

// --------------------------------------------------------------------- health
function renderHealth(h) {
  state.health = h;
  const banner = $("banner");
  banner.className = "banner " + (h.message ? h.state : "hidden");
  banner.textContent = h.message;
  $("h-state").textContent = h.state;
  $("h-lines").textContent = h.lines.toLocaleString("en");
  $("h-rate").textContent = Math.round(h.lines_per_s).toLocaleString("en");
  $("h-behind").textContent = fmt(1e3 * h.behind_s, 1) + " ms";
  $("h-lag").textContent = h.last_lag_s === null ? "–" : fmt(1e3 * h.last_lag_s, 1) + " ms";
  $("h-dropped").textContent = h.dropped_lines + (h.skipped ? ` (and ${h.skipped} balls not shown: the page fell behind)` : "");
  $("ball-count").textContent = state.mode === "live" ? h.balls : state.balls.length;
  const strip = h.strip_dn, canvas = $("strip");
  if (!strip.length) return;
  const lo = Math.min(...strip), hi = Math.max(...strip);
  canvas.width = strip.length; canvas.height = 1;  // one pixel per bin, stretched by the page's style
  const ctx = canvas.getContext("2d"), img = ctx.createImageData(strip.length, 1);
  strip.forEach((v, k) => {
    const g = hi > lo ? Math.round(255 * (v - lo) / (hi - lo)) : 128;
    img.data[4 * k] = img.data[4 * k + 1] = img.data[4 * k + 2] = g; img.data[4 * k + 3] = 255;
  });
  ctx.putImageData(img, 0, 0);
  $("strip-range").textContent = `(${fmt(lo, 1)}–${fmt(hi, 1)} DN across ${h.width} pixels)`;
}

function renderAll() {
  document.querySelectorAll(".unit-label").forEach((e) => { e.textContent = state.unit; });
  renderLast(state.shown); renderTable(); renderChart(); renderHistogram();
}

// -------------------------------------------------------- live and replayed runs
function query() {
  const p = new URLSearchParams();
  const u = state.units[state.unit];
  const lim = (id, key) => { const v = $(id).value.trim(); if (v !== "" && isFinite(Number(v))) p.set(key, String(Number(v) / u)); };
  if ($("f-flag").value) p.set("flag", $("f-flag").value);
  lim("f-min", "min_mps"); lim("f-max", "max_mps");
  return p.toString();
}

async function refreshReplay() {
  const q = query();
  $("download").href = "/api/balls.csv" + (q ? "?" + q : "");
  const r = await fetch("/api/balls" + (q ? "?" + q : ""));
  if (!r.ok) { $("table-note").textContent = await r.text(); return; }
  state.balls = (await r.json()).balls;
  renderAll();
  if (state.balls.length && (!state.shown || !state.balls.some((b) => b.index === state.shown.index))) showBall(state.balls[state.balls.length - 1].index);
}

function connectLive() {
  const after = state.balls.length ? state.balls[state.balls.length - 1].index : -1;
  const source = new EventSource(`/events?after=${after}`);
  source.addEventListener("ball", (e) => {
    const ball = JSON.parse(e.data);
    const { crop, ...summary } = ball;
    state.balls.push(summary);
    if (state.balls.length > KEEP_BALLS) state.balls.shift();
    state.shown = ball;
    renderAll();
  });
  source.addEventListener("health", (e) => renderHealth(JSON.parse(e.data)));
  source.addEventListener("skipped", (e) => { $("table-note").textContent = `${JSON.parse(e.data).balls} balls skipped`; });
  source.onerror = () => renderHealth({ ...(state.health || { lines: 0, lines_per_s: 0, behind_s: 0, last_lag_s: null, dropped_lines: 0, balls: 0, skipped: 0, strip_dn: [], width: 0 }),
    state: "disconnected", message: "the server is not answering (the watch has stopped?)" });
}

async function main() {
  const info = await (await fetch("/api/info")).json();
  state.mode = info.mode; state.units = info.units; state.flags = info.flags;
  $("title").textContent = info.title; document.title = info.title;
  const saved = localStorage.getItem("ballscan-unit");
  if (saved && saved in state.units) state.unit = saved;
  $("unit").value = state.unit;
  $("unit").addEventListener("change", () => { state.unit = $("unit").value; localStorage.setItem("ballscan-unit", state.unit); renderAll(); });
  if (state.mode === "replay") {
    for (const [word, text] of Object.entries(state.flags)) {
      const o = document.createElement("option"); o.value = word; o.textContent = word; o.title = text; $("f-flag").appendChild(o);
    }
    $("filters").classList.remove("hidden");
    $("health").classList.add("hidden");  // a saved run has no stream to watch
    $("filters").addEventListener("change", refreshReplay);
    $("filters").addEventListener("submit", (e) => { e.preventDefault(); refreshReplay(); });
    renderHealth(await (await fetch("/api/health")).json());
    await refreshReplay();
  } else {
    state.balls = (await (await fetch("/api/balls")).json()).balls;
    renderAll();
    if (state.balls.length) showBall(state.balls[state.balls.length - 1].index);
    connectLive();
  }
  document.body.dataset.ready = "1";
}

main();
