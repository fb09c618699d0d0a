// stereo-view's page: every topic of the event stream (/events) drawn where it
// belongs. Numbers the checks read are also kept as data-* attributes.
"use strict";

const $ = (selector) => document.querySelector(selector);
const state = { frame: null, images: {}, corners: null, coverage: null, spread: null, detectedAt: 0, tabPicked: false };

// ---- tabs -------------------------------------------------------------------
function showTab(view) {
  for (const t of document.querySelectorAll(".tab")) t.classList.toggle("active", t.dataset.view === view);
  for (const v of document.querySelectorAll(".view")) v.hidden = v.id !== view;
  if (view === "depth") cloudView.resize();
  connect();  // stereo-view makes only the shown view's images
}
for (const tab of document.querySelectorAll(".tab")) {
  tab.addEventListener("click", () => { state.tabPicked = true; showTab(tab.dataset.view); });
}

// ---- drawing helpers --------------------------------------------------------
// An image an event names (blob/ID), or null when stereo-view no longer
// keeps it (a newer event follows).
function loadImage(src) {
  return new Promise((resolve) => {
    const img = new Image();
    img.onload = () => resolve(img);
    img.onerror = () => resolve(null);
    img.src = src;
  });
}

// A value in [0, 1] as a colour from dark blue through green to yellow (viridis-like).
function scaleColour(t) {
  const stops = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  t = Math.min(1, Math.max(0, t)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(t)), f = t - i;
  return stops[i].map((c, k) => Math.round(c + (stops[i + 1][k] - c) * f));
}

// Relative luminance of an [r, g, b] colour, 0 (black) to 1 (white).
const luminance = ([r, g, b]) => (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;

function fmt(value, digits = 3) { return value === null || value === undefined ? "—" : Number(value).toFixed(digits); }

// ---- calibration view -------------------------------------------------------
function drawCamera(side) {
  const figure = $("#cam-" + side), canvas = figure.querySelector("canvas");
  const image = state.frame && state.frame[side], img = state.images[side];
  if (!image || !img) return;
  canvas.width = img.width; canvas.height = img.height;
  const ctx = canvas.getContext("2d");
  ctx.drawImage(img, 0, 0);
  const sx = img.width / image.width, sy = img.height / image.height;
  // The coverage of the accepted views, on the cells' edges only: the
  // board inside them stays as the camera sees it.
  const cov = state.coverage;
  let covered = 0;
  if (cov && cov.grid_rows > 0) {
    const grid = cov["coverage_" + side], cw = img.width / cov.grid_cols, ch = img.height / cov.grid_rows;
    const most = Math.max(1, ...grid.flat()), mark = Math.min(cw, ch) / 4;
    for (let r = 0; r < cov.grid_rows; ++r)
      for (let c = 0; c < cov.grid_cols; ++c) {
        const n = grid[r][c], x = c * cw, y = r * ch;
        covered += n;
        if (n === 0) {  // red corner marks: no corner here yet
          ctx.strokeStyle = "rgba(255, 60, 60, 0.7)";
          ctx.lineWidth = 2;
          ctx.beginPath();
          for (const [px, py, dx, dy] of [[x, y, 1, 1], [x + cw, y, -1, 1], [x, y + ch, 1, -1], [x + cw, y + ch, -1, -1]]) {
            ctx.moveTo(px + dx * 3, py + dy * (3 + mark)); ctx.lineTo(px + dx * 3, py + dy * 3); ctx.lineTo(px + dx * (3 + mark), py + dy * 3);
          }
          ctx.stroke();
        } else {  // a blue frame, the thicker the more corners
          ctx.strokeStyle = "rgba(40, 110, 255, 0.85)";
          ctx.lineWidth = 1 + 5 * n / most;
          ctx.strokeRect(x + ctx.lineWidth / 2 + 1, y + ctx.lineWidth / 2 + 1, cw - ctx.lineWidth - 2, ch - ctx.lineWidth - 2);
        }
      }
  }
  figure.dataset.coverage = covered;
  // The corners of the newest detection.
  const corners = state.corners && state.corners[side];
  let drawn = 0;
  if (corners && state.corners.frame_id === state.frame.frame_id && corners.width === image.width &&
      corners.height === image.height) {
    ctx.strokeStyle = "#00ff00";
    ctx.lineWidth = 2;
    for (const [u, v] of corners.points) {
      ctx.beginPath();
      ctx.arc((u + 0.5) * sx, (v + 0.5) * sy, 4, 0, 2 * Math.PI);
      ctx.stroke();
      ++drawn;
    }
  }
  figure.dataset.corners = drawn;
  figure.dataset.frameId = state.frame.frame_id;
  stamp(figure.querySelector(".age"), state.frame.at_us);
  figure.querySelector(".info").textContent =
    `frame ${state.frame.frame_id}, ${image.width}×${image.height}, ${drawn} corners` +
    (state.corners ? "" : " (waiting for stereo-detect's corners of a frame)");
}

// At most one redraw per displayed frame, whatever the number of events.
let redraw = null;
function drawPair() {
  if (redraw === null) redraw = requestAnimationFrame(() => { redraw = null; drawCamera("left"); drawCamera("right"); });
}

// Each image decoded once, when it comes. The calibration view shows what the
// detector saw: each frame it has found corners in (or none), with them; the
// newest frames only while no detection came for 30 s (no stereo-detect).
async function showFrame(frame, corners) {
  if (!corners && Date.now() - state.detectedAt < 30000) return;
  const images = {};
  for (const side of ["left", "right"]) {
    if (!frame[side]) continue;
    images[side] = await loadImage(frame[side].src);
    if (!images[side]) return;
  }
  state.frame = frame;
  state.images = images;
  state.corners = corners;
  if (corners) state.detectedAt = Date.now();
  drawPair();
}

// camera_calibration's four bars (stereo-view measures every board found);
// "enough" lights the Solve button once stereo-calibrate has stereo views.
function showSpread(spread) {
  state.spread = spread;
  $("#spread-boards").textContent = spread.boards;
  const bars = $("#spread .bars");
  bars.replaceChildren();
  for (const bar of spread.bars) {
    const fill = Object.assign(document.createElement("span"), { className: "fill" + (bar.progress >= 1 ? " full" : "") });
    fill.style.width = `${Math.round(100 * bar.progress)}%`;
    const track = Object.assign(document.createElement("span"), { className: "track" });
    track.dataset.name = bar.name;
    track.dataset.progress = bar.progress;
    track.append(fill);
    bars.append(Object.assign(document.createElement("span"), { textContent: bar.name }), track,
                Object.assign(document.createElement("span"), {
                  className: "range", textContent: bar.low === null ? "—" : `${fmt(bar.low, 2)} to ${fmt(bar.high, 2)}` }));
  }
  stamp($("#spread-age"), spread.at_us);
  lightSolve();
}

function lightSolve() {
  const enough = Boolean(state.spread && state.spread.enough && state.coverage && state.coverage.views_stereo > 0 &&
                         state.coverage.state === "collecting");
  $("#spread").dataset.enough = enough;
  const solve = $("button[data-command=solve]");
  solve.classList.toggle("ready", enough);
  solve.title = solve.disabled ? solve.title : enough ? "enough different boards: solve now" : "not enough different boards yet";
}

// The calibration stereo-view rectifies with: K, the distortion, R, T, the baseline.
function showCalibration(calibration) {
  $("#calibration-in-use").hidden = false;
  $("#calibration-source").textContent = "from " + calibration.source;
  const body = $("#intrinsics tbody");
  body.replaceChildren();
  for (const c of calibration.cameras) {
    const row = body.insertRow();
    row.dataset.camera = c.name;
    const names = c.model.startsWith("bspline") ? "α" : "k";
    const coeffs = c.coeffs.map((v, i) => `${names}${i + 1} ${v.toPrecision(4)}`).join(", ");
    for (const text of [c.name, c.model, fmt(c.K[0][0], 2), fmt(c.K[1][1], 2), fmt(c.K[0][2], 2), fmt(c.K[1][2], 2),
                        c.p1.toPrecision(3), c.p2.toPrecision(3), coeffs])
      row.insertCell().textContent = text;
  }
  $("#rotation").textContent = "[" + calibration.R.map((r) => r.map((v) => fmt(v, 5)).join(" ")).join("; ") + "]";
  $("#translation").textContent = "(" + calibration.T.map((v) => fmt(v, 4)).join(", ") + ")";
  $("#baseline").textContent = fmt(calibration.baseline, 4);
  $("#baseline").dataset.metres = calibration.baseline;
  cloudView.setRig(calibration);
  stamp($("#calibration-age"), calibration.at_us);
}

function showCoverage(cov) {
  state.coverage = cov;
  lightSolve();
  $("#calib-state").textContent = cov.state;
  $("#views").textContent = `${cov.views_left} left, ${cov.views_right} right, ${cov.views_stereo} stereo`;
  $("#calib-rms").textContent = fmt(cov.rms);
  $("#calib-heldout").textContent = fmt(cov.heldout_rms);
  $("#hint").textContent = cov.hint || "—";
  stamp($("#coverage-age"), cov.at_us);
  drawPair();
}

// A map (rows of values, negative: none) on a canvas, with its largest value.
function drawMap(title, rows, unit) {
  const figure = document.createElement("figure"), canvas = document.createElement("canvas");
  const nrows = rows.length, ncols = nrows ? rows[0].length : 0;
  canvas.width = 32 * Math.max(1, ncols); canvas.height = 32 * Math.max(1, nrows);
  canvas.style.width = "320px";
  const ctx = canvas.getContext("2d");
  // The scale's top at the 95th percentile, so that a few extreme cells (the
  // image's corners, far from any view) do not flatten the rest.
  const values = rows.flat().filter((v) => v >= 0).sort((a, b) => a - b);
  const most = values.length ? values[Math.floor(0.95 * (values.length - 1))] : 0;
  ctx.fillStyle = "#ccc";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  rows.forEach((row, r) => row.forEach((v, c) => {
    if (v < 0) return;
    const [R, G, B] = scaleColour(most > 0 ? v / most : 0);
    ctx.fillStyle = `rgb(${R},${G},${B})`;
    ctx.fillRect(c * 32, r * 32, 32, 32);
  }));
  const caption = document.createElement("figcaption");
  caption.textContent = `${title}: yellow ${fmt(most)} ${unit} or more, up to ${fmt(values[values.length - 1])}; grey: none`;
  figure.append(canvas, caption);
  return figure;
}

// The uncertainty of a quick solve of the views so far, until a solve newer than it.
function showPreview(preview) {
  state.preview = preview;
  $("#preview-model").textContent = preview.chosen;
  const maps = $("#preview .maps");
  maps.replaceChildren(...preview.cameras.map((c) => drawMap(c.name + " projection uncertainty", c.uncertainty_px, "px")));
  stamp($("#preview-age"), preview.at_us);
  $("#preview").hidden = Boolean(state.result && state.result.at_us > preview.at_us);
}

function showResult(result) {
  state.result = result;
  if (state.preview) $("#preview").hidden = state.preview.at_us < result.at_us;
  $("#result").hidden = false;
  $("#chosen-model").textContent = result.chosen;
  stamp($("#result-age"), result.at_us);
  const body = $("#models tbody");
  body.replaceChildren();
  for (const m of result.models) {
    const tr = document.createElement("tr");
    tr.dataset.model = m.model;
    tr.classList.toggle("chosen", m.model === result.chosen);
    const cells = [m.model, fmt(m.left_rms, 4), fmt(m.left_heldout_rms, 4), fmt(m.right_rms, 4),
                   fmt(m.right_heldout_rms, 4), fmt(m.stereo_rms, 4), m.error ? "failed: " + m.error : ""];
    for (const [k, text] of cells.entries()) {
      const td = document.createElement("td");
      td.textContent = text;
      td.className = ["model", "left_rms", "left_heldout_rms", "right_rms", "right_heldout_rms", "stereo_rms", "error"][k];
      tr.append(td);
    }
    for (const key of ["left_rms", "right_rms", "stereo_rms", "left_heldout_rms", "right_heldout_rms"])
      if (m[key] !== null) tr.dataset[key.replace(/_(\w)/g, (_, c) => c.toUpperCase())] = m[key];
    body.append(tr);
  }
  const maps = $("#maps");
  maps.replaceChildren();
  for (const camera of result.cameras) {
    maps.append(drawMap(camera.name + " residual RMS", camera.residual_rms_px, "px"));
    maps.append(drawMap(camera.name + " projection uncertainty", camera.uncertainty_px, "px"));
  }
}

function showStatus(status) {
  clock.offsetMs = status.now_us / 1000 - Date.now();
  clock.statusAt = Date.now();
  clock.freshness = status.freshness;
  clock.recording = status.recording;
  clock.processes = status.processes;
  const rec = status.recording, recording = $("#recording");
  recording.hidden = !rec;
  if (rec) {
    // A rolling recording never stops: once full it holds the last minutes, older ones deleted.
    const span = rec.window_s === null ? "" : ` the last ${fmt(rec.window_s / 60, 1)} min,`;
    recording.textContent = rec.mb === null ? "not recording yet"
      : rec.rolling && rec.capped ? `recording rolling:${span} ${fmt(rec.mb, 0)} MB in ${rec.files} files, older deleted`
      : rec.rolling ? `recording ${fmt(rec.mb, 0)} of ${rec.cap_mb} MB, then rolling`
      : rec.capped ? `recording stopped at ${fmt(rec.mb, 0)} MB` : `recording ${fmt(rec.mb, 0)} of ${rec.cap_mb} MB`;
    recording.className = rec.capped && !rec.rolling ? "warn" : "";
    recording.dataset.rolling = Boolean(rec.rolling && rec.capped);
  }
  if (!state.tabPicked && status.first_view !== document.querySelector(".tab.active").dataset.view) {
    state.tabPicked = true;  // once: then the user's choice
    showTab(status.first_view);
  }
  showFreshness();
  const clouds = status.freshness.STEREO_CLOUD_FILTERED;
  $("#cloud-rate").textContent = clouds && clouds.rate_hz && !clouds.stale ? `${fmt(clouds.rate_hz, 1)} clouds/s` : "";
  showProcesses(status.processes);
  stamp($("#processes-age"), status.now_us);
  const why = status.commands_refused;
  state.commandsRefused = why;
  for (const button of document.querySelectorAll("button.command, button.remove")) {
    button.disabled = why !== "";
    button.title = why;
  }
  lightSolve();
  if (why) setCommandNote(why, "error");
  document.body.dataset.browserSkipped = status.counters.browsers.skipped;
}

// Posts a command (its JSON body) to stereo-view; says `what` was sent, or why not.
async function sendCommand(body, what) {
  const reply = await fetch("command", {
    method: "POST",
    headers: { "Content-Type": "application/json", "X-Widestereo-Page": "1" },
    body: JSON.stringify(body),
  });
  const answer = await reply.json();
  if (reply.ok) setCommandNote(`${what} sent`, "sent");
  else setCommandNote(answer.error, "error");
}
for (const button of document.querySelectorAll("button.command"))
  button.addEventListener("click", () => sendCommand({ command: button.dataset.command }, button.dataset.command));

function setCommandNote(text, kind) {
  const note = $("#command-why");
  note.textContent = text;
  note.className = kind;
}

// ---- depth view ---------------------------------------------------------------
async function showRectified(event) {
  for (const side of ["left", "right"]) {
    const canvas = $("#rect-" + side + " canvas"), img = await loadImage(event[side]);
    if (!img) return;
    canvas.width = img.width; canvas.height = img.height;
    const ctx = canvas.getContext("2d");
    ctx.drawImage(img, 0, 0);
    ctx.strokeStyle = "#ffeb3b";
    ctx.lineWidth = 1;
    for (let k = 1; k < 8; ++k) {
      const y = Math.round(k * img.height / 8) + 0.5;
      ctx.beginPath(); ctx.moveTo(0, y); ctx.lineTo(img.width, y); ctx.stroke();
    }
  }
  $("#rect-right .info").textContent = `frame ${event.frame_id}, ${event.width}×${event.height}`;
  for (const side of ["left", "right"]) stamp($(`#rect-${side} .age`), event.at_us);
}

function showDisparity(event) {
  $("#disparity").src = event.src;
  $("#disparity-figure").dataset.frameId = event.frame_id;
  const legend = $("#legend");
  legend.replaceChildren();
  for (const tick of event.ticks) {
    const span = document.createElement("span");
    span.dataset.disparity = tick.disparity;
    span.dataset.metres = tick.metres;
    span.style.background = `rgb(${tick.rgb.join(",")})`;
    span.style.color = luminance(tick.rgb) < 0.5 ? "#fff" : "#000";  // readable on every colour
    span.textContent = `${fmt(tick.metres, 2)} m`;
    legend.append(span);
  }
  legend.dataset.f = event.f;
  legend.dataset.baseline = event.baseline;
  legend.dataset.rectification = event.rectification;
  $("#disparity-figure .info").textContent =
    `frame ${event.frame_id}, ${event.rectification}, disparities ${event.min_disparity} to ${event.max_disparity} px (far to near)`;
  stamp($("#disparity-figure .age"), event.at_us);
}

function showCloudStats(stats) {
  $("#cloud-frame").textContent = stats.frame_id;
  $("#cloud-points").textContent = stats.points;
  $("#plane").textContent = stats.plane_found
    ? `n = (${stats.plane_normal.map((v) => fmt(v, 3)).join(", ")}), inlier RMS ${fmt(stats.inlier_rms * 1000, 1)} mm`
    : "not found";
  $("#plane-distance").textContent = stats.plane_found ? fmt(Math.abs(stats.plane_offset), 4) : "—";
  const panel = $("#cloud-points");
  panel.dataset.frameId = stats.frame_id;
  panel.dataset.points = stats.points;
  panel.dataset.planeOffset = stats.plane_offset;
  stamp($("#cloud-stats-age"), stats.at_us);
  cloudView.setPlane(stats);
}

function showHealth(health) {
  $("#health-verdict").textContent = health.verdict;
  $("#health-verdict").dataset.verdict = health.verdict;
  $("#health-dy").textContent = fmt(health.dy_median_px, 3);
  $("#health-matches").textContent = `${health.matches} matches in ${health.frames} frames`;
  stamp($("#health-age"), health.at_us);
}

// The filtered cloud in 3-D (cloud3d.js), its age and rate, the point picked.
const cloudView = (() => {
  const container = $("#cloud");
  let scene = null, last = null, xyz = null, framed = false, pointSize = 0.01, extent = null, stats = null;
  try {
    scene = CloudScene(container);
  } catch (e) {
    container.textContent = "no WebGL in this browser: " + e.message;
  }
  // A cloud event: its points fetched (float32 x y z, little-endian), then drawn.
  async function show(event) {
    const reply = await fetch(event.src);
    if (!reply.ok) return;  // no longer kept: a newer cloud follows
    last = event;
    xyz = new Float32Array(await reply.arrayBuffer());
    draw();
  }
  function resize() { if (scene) scene.resize(); }
  function draw() {
    if (!last) return;
    container.dataset.frameId = last.frame_id;
    container.dataset.shown = xyz.length / 3;
    $("#cloud-figure .info").textContent = `frame ${last.frame_id}: ${last.npoints} points, ${xyz.length / 3} shown`;
    const wasEmpty = !$("#cloud-figure").dataset.filled;
    stamp($("#cloud-figure .age"), last.at_us);
    if (wasEmpty) resize();
    if (!scene) return;
    const byRange = $("#colour-by").value === "range";
    const values = new Float32Array(xyz.length / 3);
    for (let i = 0; i < values.length; ++i) {
      const x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
      values[i] = byRange ? Math.hypot(x, y, z) : -y;
    }
    let lo = Infinity, hi = -Infinity;
    for (const v of values) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    const colours = new Float32Array(xyz.length);
    values.forEach((v, i) => {
      const rgb = scaleColour(hi > lo ? (v - lo) / (hi - lo) : 0.5);
      for (let k = 0; k < 3; ++k) colours[3 * i + k] = rgb[k] / 255;
    });
    const c = [0, 0, 0];
    for (let i = 0; i < xyz.length; ++i) c[i % 3] += xyz[i] / (xyz.length / 3);
    let r = 0;
    for (let i = 0; i < xyz.length; i += 3) r = Math.max(r, Math.hypot(xyz[i] - c[0], xyz[i + 1] - c[1], xyz[i + 2] - c[2]));
    extent = { centre: c, radius: Math.max(r, 0.1) };
    if (!framed) {  // the first cloud: its centre and extent frame the view
      framed = true;
      scene.frame(extent.centre, extent.radius);
      pointSize = extent.radius / 120;
    }
    scene.setCloud(xyz, colours, pointSize);
    drawPlane();
  }
  // stereo-cloud's plane, about the cloud shown (CLOUD_STATS).
  function setPlane(cloudStats) {
    stats = cloudStats;
    drawPlane();
  }
  function drawPlane() {
    if (!scene || !extent || !stats) return;
    scene.setPlane(stats.plane_found ? stats.plane_normal : null, stats.plane_offset, extent.centre, 1.5 * extent.radius);
    container.dataset.helpers = scene.helperNames().join(" ");
  }
  // A click, not a drag (which orbits): the point under it, its coordinates and range.
  if (scene) {
    let down = null;
    // The pointer's move on the screen, not on the canvas: the page may reflow
    // between (a panel fills); the point picked is the one pressed on.
    scene.canvas.addEventListener("pointerdown", (e) => { down = [e.clientX, e.clientY, e.offsetX, e.offsetY]; });
    scene.canvas.addEventListener("pointerup", (e) => {
      if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
      const point = scene.pick(down[2], down[3]), picked = $("#picked");
      if (!point) { picked.textContent = "no point there: click on the cloud"; return; }
      const range = Math.hypot(...point);
      Object.assign(picked.dataset, { x: point[0], y: point[1], z: point[2], range });
      picked.textContent = `picked x ${fmt(point[0], 3)}, y ${fmt(point[1], 3)}, z ${fmt(point[2], 3)} m; ` +
                           `range ${fmt(range, 3)} m (left rectified frame: x right, y down, z ahead)`;
    });
  }
  // The rig's cameras, from the calibration in use.
  function setRig(calibration) {
    const left = calibration.cameras[0];
    if (!scene || !left) return;
    scene.setRig(calibration.baseline, left.width / 2 / left.K[0][0], left.height / 2 / left.K[1][1]);
    container.dataset.helpers = scene.helperNames().join(" ");
  }
  $("#colour-by").addEventListener("change", draw);
  return { show, resize, setRig, setPlane };
})();

// ---- the event stream ---------------------------------------------------------
// One stream, for the view shown: stereo-view makes a view's images,
// disparities and clouds only while some page shows it.
let source = null;
function connect() {
  if (source) source.close();
  source = new EventSource("events?view=" + document.querySelector(".tab.active").dataset.view);
  const on = (topic, fn) => source.addEventListener(topic, (e) => fn(JSON.parse(e.data)));
  source.onopen = showFreshness;  // "live" only once data is seen flowing
  source.onerror = showFreshness;
  on("frame", (e) => showFrame(e, null));
  on("detected", (e) => showFrame(e.frame, e.corners));
  on("coverage", showCoverage);
  on("spread", showSpread);
  on("calibration", showCalibration);
  on("result", showResult);
  on("views", showViews);
  on("preview", showPreview);
  on("status", showStatus);
  on("rectified", showRectified);
  on("disparity", showDisparity);
  on("cloud", (e) => cloudView.show(e));
  on("cloud_stats", showCloudStats);
  on("health", showHealth);
}
cloudView.resize();
connect();
