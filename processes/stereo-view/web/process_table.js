// stereo-view's page: the process table (view.js calls it with each status).
"use strict";

// stereo-status's table as HTML: a body per process (a row per channel,
// then its stage times and last error, wrapped), ended ones greyed.
function showProcesses(processes) {
  const table = $("#processes");
  for (const body of table.querySelectorAll("tbody")) body.remove();
  const cell = (row, text, className) =>
    row.appendChild(Object.assign(document.createElement("td"), { textContent: text, className: className || "" }));
  for (const p of processes) {
    const body = document.createElement("tbody");
    body.className = p.ended ? "ended" : p.gone ? "gone" : "";
    body.dataset.process = p.who;
    body.dataset.state = p.state;
    const channels = p.channels.length ? p.channels : [null];
    channels.forEach((c, i) => {
      const row = body.insertRow();
      for (const [text, name] of i === 0 ? [[p.who, "who"], [p.state, "state"], [p.pid, "pid"], [p.uptime, "uptime"]]
                                         : [["", ""], ["", ""], ["", ""], ["", ""]])
        cell(row, text, name);
      if (!c) return;
      row.dataset.channel = c.channel;
      cell(row, c.channel);
      for (const key of ["in", "out", "rate", "lost", "skipped", "rejected"])
        cell(row, key === "rate" ? (c.rate === null ? "-" : c.rate.toFixed(1)) : c[key], key);
    });
    const note = (text, className) => {
      const td = cell(body.insertRow(), text, "note " + className);
      td.colSpan = 11;
    };
    if (p.stages.length) note("ms per frame, median/p99: " + p.stages.join(", "), "stages");
    if (p.last_error) note("last error: " + p.last_error, "error");
    table.append(body);
  }
}
