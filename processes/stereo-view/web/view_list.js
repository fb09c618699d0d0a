// stereo-view's page: the views stereo-calibrate holds (the "views" event),
// each a card: its frame (the view's name), a thumbnail of its left image
// (its right one when the left did not see the board), the board's outline,
// its RMS in the last solve, and a button that asks stereo-calibrate to
// remove it (with the rig key). An event is the whole list (a new stream,
// or one that missed an update) or its change from the list before (put:
// views new or changed, oldest first; gone: [frame_id, utime] pairs), so
// that an update costs what changed, in bytes and in cards drawn.
// It reads view.js's $, fmt, loadImage, state and sendCommand when it runs.
"use strict";

const thumbnails = new Map();  // src -> a promise of its image (null: no longer kept)

function thumbnailImage(src) {
  if (!thumbnails.has(src)) thumbnails.set(src, loadImage(src));
  return thumbnails.get(src);
}

// The thumbnail (or a grey box) with the board's outline over it.
async function drawViewCard(canvas, view, size) {
  const [side, colour] = view.left_corners > 0 ? ["left", "#00e000"] : ["right", "#ff9800"];
  const camera = side === "left" ? 0 : 1, width = size.width[camera] || 1, height = size.height[camera] || 1;
  canvas.width = 128;
  canvas.height = Math.max(1, Math.round(128 * height / width));
  const ctx = canvas.getContext("2d");
  const img = view.thumbnail ? await thumbnailImage(view.thumbnail) : null;
  ctx.fillStyle = "#546e7a";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  if (img) ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
  canvas.dataset.image = img ? "1" : "0";
  const outline = view[side + "_outline"], sx = canvas.width / width, sy = canvas.height / height;
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2;
  ctx.beginPath();
  outline.forEach(([u, v], k) => (k ? ctx.lineTo : ctx.moveTo).call(ctx, (u + 0.5) * sx, (v + 0.5) * sy));
  ctx.closePath();
  ctx.stroke();
}

function rmsText(view) {
  if (view.left_rms === null && view.right_rms === null) return "not solved yet";
  return `RMS left ${fmt(view.left_rms, 3)}, right ${fmt(view.right_rms, 3)} px`;
}

// The list as this page holds it: each view and its card, by frame id and utime.
const viewList = { size: null, views: new Map(), cards: new Map() };
const viewKey = (frameId, utime) => `${frameId}:${utime}`;

function viewCard(view) {
  const card = document.createElement("figure");
  card.className = "view-card";
  Object.assign(card.dataset, { frameId: view.frame_id, utime: view.utime });
  if (view.left_rms !== null) card.dataset.leftRms = view.left_rms;
  if (view.right_rms !== null) card.dataset.rightRms = view.right_rms;
  const canvas = document.createElement("canvas");
  drawViewCard(canvas, view, viewList.size);
  const remove = Object.assign(document.createElement("button"), { className: "remove", textContent: "remove" });
  remove.disabled = state.commandsRefused !== "";
  remove.title = remove.disabled ? state.commandsRefused || "" : `take the view of frame ${view.frame_id} out`;
  remove.addEventListener("click", () => {
    remove.disabled = true;
    sendCommand({ command: "remove", frame: view.frame_id, utime: view.utime }, `remove frame ${view.frame_id}`);
  });
  const caption = document.createElement("figcaption");
  caption.append(Object.assign(document.createElement("b"), { textContent: `frame ${view.frame_id}` }),
                 document.createElement("br"),
                 `${view.left_corners} + ${view.right_corners} corners`, document.createElement("br"),
                 Object.assign(document.createElement("span"), { className: "rms", textContent: rmsText(view) }),
                 document.createElement("br"), remove);
  card.append(canvas, caption);
  return card;
}

// The views, newest first. A view whose RMS is over twice the median of the
// views' is marked: the likeliest to remove.
function showViews(event) {
  const list = $("#view-list"), cards = list.querySelector(".view-cards");
  viewList.size = { width: event.width, height: event.height };
  if (event.views) {  // the whole list
    viewList.views = new Map(event.views.map((v) => [viewKey(v.frame_id, v.utime), v]));
    viewList.cards = new Map([...viewList.views].map(([key, v]) => [key, viewCard(v)]));
    cards.replaceChildren(...viewList.cards.values());
  } else {  // its change
    for (const [frameId, utime] of event.gone) {
      const key = viewKey(frameId, utime);
      viewList.cards.get(key)?.remove();
      viewList.cards.delete(key);
      viewList.views.delete(key);
    }
    for (const view of event.put) {  // oldest first: a new one goes before the others
      const key = viewKey(view.frame_id, view.utime), card = viewCard(view), old = viewList.cards.get(key);
      if (old) old.replaceWith(card);
      else cards.prepend(card);
      viewList.cards.set(key, card);
      viewList.views.set(key, view);
    }
  }
  const views = [...viewList.views.values()];
  list.dataset.views = views.length;
  $("#view-count").textContent = views.length;
  const worst = (v) => Math.max(v.left_rms ?? -1, v.right_rms ?? -1);
  const solved = views.map(worst).filter((r) => r >= 0).sort((a, b) => a - b);
  const median = solved.length ? solved[Math.floor((solved.length - 1) / 2)] : null;
  for (const [key, card] of viewList.cards)
    card.classList.toggle("worst", median !== null && worst(viewList.views.get(key)) > 2 * median);
  const shown = new Set(views.map((v) => v.thumbnail));
  for (const src of thumbnails.keys())  // the thumbnails of views gone
    if (!shown.has(src)) thumbnails.delete(src);
  stamp($("#view-list-age"), event.at_us);
}
