// stereo-view's page: how fresh what it shows is (view.js calls it; it
// reads view.js's $ and the stream, `source`, when it runs).
"use strict";

// Every panel shows how old what it shows is, on stereo-view's clock (each
// event's at_us; the status event, every second, gives that clock's now).
// A channel stereo-view no longer hears is named in the banner; "live" means
// the stream is open and what it carries is flowing.
const STALE_MS = 3000;
const clock = { offsetMs: 0, statusAt: 0, freshness: {}, recording: null, processes: [] };
const serverNowMs = () => Date.now() + clock.offsetMs;

// Marks `element` as showing what stereo-view received at at_us.
function stamp(element, atUs) {
  if (!element || atUs === undefined) return;
  element.dataset.at = atUs;
  const figure = element.closest("figure");
  if (figure) figure.dataset.filled = "1";
  const waiting = element.parentElement.querySelector(".waiting");  // what it waited for has come
  if (waiting) waiting.hidden = true;
  refreshAge(element);
}

function refreshAge(element) {
  const seconds = Math.max(0, (serverNowMs() - element.dataset.at / 1000) / 1000);
  element.dataset.ageS = seconds.toFixed(1);
  element.textContent = seconds < 1 ? "just now" : `${seconds.toFixed(0)} s ago`;
  // What comes once (a solve, a calibration) is not stale for being old.
  element.classList.toggle("old", !element.classList.contains("once") && seconds * 1000 > STALE_MS);
}

// What the sender's heartbeats say of it: " (stopped)", " (gone)", " (running,
// but sends nothing)"; "" when no heartbeat of it was heard.
function senderState(name) {
  const mine = clock.processes.filter((p) => p.who === name || p.who.startsWith(name + "@"));
  if (!name || !mine.length) return "";
  const live = mine.find((p) => !p.ended && !p.gone);
  return live ? ` (${live.state}, but sends nothing)` : ` (${mine[mine.length - 1].state})`;
}

const clockTime = (serverUs) => new Date(serverUs / 1000 - clock.offsetMs).toLocaleTimeString();

function showFreshness() {
  for (const element of document.querySelectorAll(".age[data-at]")) refreshAge(element);
  const open = source && source.readyState === EventSource.OPEN;
  const lines = [];
  if (open && clock.statusAt && Date.now() - clock.statusAt > STALE_MS)
    lines.push(`stereo-view has sent nothing since ${new Date(clock.statusAt).toLocaleTimeString()}: what the page shows is from then`);
  const stale = Object.entries(clock.freshness).filter(([, f]) => f.stale);
  for (const [channel, f] of stale)
    lines.push(`Stale: no ${channel} from ${f.source || "its sender"}${senderState(f.source)} since ` +
               `${clockTime(f.last_us)} (${f.age_s.toFixed(0)} s): what the page shows of it is from then`);
  const rec = clock.recording, notes = [];
  if (rec && rec.capped && !rec.rolling)
    notes.push(`Recording stopped: ${rec.path} reached its cap of ${rec.cap_mb} MB at ${clockTime(rec.capped_us)}; ` +
               "nothing after is recorded (the processes go on; more: --max-log-mb)");
  const banner = $("#stale");
  banner.replaceChildren(...lines.concat(notes).map((text) => Object.assign(document.createElement("div"), { textContent: text })));
  banner.hidden = lines.length + notes.length === 0;
  banner.dataset.recordingCapped = Boolean(rec && rec.capped && !rec.rolling);
  banner.dataset.channels = stale.map(([channel]) => channel).join(" ");
  const flowing = Object.values(clock.freshness).some((f) => !f.stale);
  const [text, className, name] = !open ? [source ? "reconnecting…" : "connecting…", "off", "off"]
    : lines.length ? ["stale", "warn", "stale"] : flowing ? ["live", "on", "live"] : ["no data yet", "warn", "waiting"];
  const connection = $("#connection");
  connection.textContent = text;
  connection.className = className;
  connection.dataset.state = name;
}
setInterval(showFreshness, 1000);
