// player-view's live page: draws the frames the tool sends over its
// WebSocket, as the PNG renderer draws them (lib/view/renderer.cpp): map
// under everything, then areas, trails, dots, ellipses, bodies.
"use strict";

const canvas = document.getElementById("view");
const context = canvas.getContext("2d");
const statusLine = document.getElementById("status");
const legend = document.getElementById("legend");
const follow = document.getElementById("follow");

let frame = null;
let mapImage = null;  // an offscreen canvas, one pixel a cell
let wallImage = null;  // the walls alone, drawn again over cones and fans
let mapInfo = null;
let centre = { x: 0, y: 0 };  // the world point at the canvas centre
let pixelsPerMetre = 60;

function resize() {
  canvas.width = canvas.clientWidth;
  canvas.height = canvas.clientHeight;
  draw();
}

function toPixel(x, y) {
  return [canvas.width / 2 + (x - centre.x) * pixelsPerMetre, canvas.height / 2 - (y - centre.y) * pixelsPerMetre];
}

function path(points, close) {
  context.beginPath();
  for (let i = 0; i + 1 < points.length; i += 2) {
    const [px, py] = toPixel(points[i], points[i + 1]);
    if (i === 0) context.moveTo(px, py); else context.lineTo(px, py);
  }
  if (close) context.closePath();
}

function drawMap(image) {
  if (!image) return;
  const [left, top] = toPixel(mapInfo.origin[0], mapInfo.origin[1] + mapInfo.height * mapInfo.resolution);
  const size = mapInfo.resolution * pixelsPerMetre;
  context.imageSmoothingEnabled = false;
  context.drawImage(image, left, top, mapInfo.width * size, mapInfo.height * size);
}

function drawBody(body) {
  const [x, y, yaw] = body.pose;
  const c = Math.cos(yaw), s = Math.sin(yaw);
  const l = body.length / 2, w = body.width / 2;
  const corner = (a, b) => [x + c * a - s * b, y + s * a + c * b];
  path([...corner(l, w), ...corner(-l, w), ...corner(-l, -w), ...corner(l, -w)], true);
  if (body.filled) {
    context.fillStyle = body.colour;
    context.fill();
  } else {
    context.strokeStyle = body.colour;
    context.lineWidth = 2;
    context.stroke();
  }
  path([...corner(0, 0), ...corner(l * 1.4, 0)], false);
  context.strokeStyle = body.filled ? "#ffffff" : body.colour;
  context.lineWidth = 2;
  context.stroke();
}

function draw() {
  context.fillStyle = mapImage ? "#cdcdcd" : "#ffffff";
  context.fillRect(0, 0, canvas.width, canvas.height);
  if (!frame) return;
  if (follow.checked) centre = { x: frame.centre[0], y: frame.centre[1] };
  drawMap(mapImage);
  for (const area of frame.areas) {
    path(area.points, true);
    context.fillStyle = area.fill;
    context.fill();
  }
  drawMap(wallImage);
  for (const line of frame.lines) {
    path(line.points, false);
    context.strokeStyle = line.colour;
    context.lineWidth = 2;
    context.stroke();
  }
  for (const dots of frame.dots) {
    context.fillStyle = dots.colour;
    const r = dots.radius;
    for (let i = 0; i + 1 < dots.points.length; i += 2) {
      const [px, py] = toPixel(dots.points[i], dots.points[i + 1]);
      context.fillRect(px - r, py - r, 2 * r + 1, 2 * r + 1);
    }
  }
  for (const e of frame.ellipses) {
    const [px, py] = toPixel(e.centre[0], e.centre[1]);
    context.beginPath();
    context.ellipse(px, py, e.a * pixelsPerMetre, e.b * pixelsPerMetre, -e.angle, 0, 2 * Math.PI);
    context.strokeStyle = e.colour;
    context.lineWidth = 2;
    context.stroke();
  }
  for (const body of frame.bodies) drawBody(body);
  context.font = "13px sans-serif";
  for (const label of frame.labels ?? []) {
    const [px, py] = toPixel(label.at[0], label.at[1]);
    context.fillStyle = label.colour;
    context.fillText(label.text, px + 6, py - 6);  // beside the marker, as the pictures put it
  }
}

function showLegend() {
  legend.replaceChildren(...frame.legend.map((entry) => {
    const line = document.createElement("div");
    line.textContent = entry.text;
    line.style.color = entry.colour;
    return line;
  }));
}

function takeMap(message) {
  mapInfo = message;
  const bytes = atob(message.cells);
  mapImage = document.createElement("canvas");
  mapImage.width = message.width;
  mapImage.height = message.height;
  wallImage = document.createElement("canvas");
  wallImage.width = message.width;
  wallImage.height = message.height;
  const mapContext = mapImage.getContext("2d");
  const wallContext = wallImage.getContext("2d");
  const pixels = mapContext.createImageData(message.width, message.height);
  const walls = wallContext.createImageData(message.width, message.height);
  const grey = [255, 205, 0];  // free, unknown, occupied
  for (let row = 0; row < message.height; row++) {
    // Cells start at the lowest y; images at the top.
    const imageRow = message.height - 1 - row;
    for (let col = 0; col < message.width; col++) {
      const value = grey[bytes.charCodeAt(row * message.width + col)] ?? 205;
      const at = 4 * (imageRow * message.width + col);
      pixels.data[at] = pixels.data[at + 1] = pixels.data[at + 2] = value;
      pixels.data[at + 3] = 255;
      if (value === 0) walls.data[at + 3] = 255;  // black where a wall is, clear elsewhere
    }
  }
  mapContext.putImageData(pixels, 0, 0);
  wallContext.putImageData(walls, 0, 0);
}

// Driving (--drive): the dead-man rule starts here. A command is sent while
// a key or button is held, renewed every 0.2 s (the tool stops a robot whose
// page falls silent), and a stop when it is released or the page loses
// focus; the tool stops the robot when this socket closes.
let socket = null;
let driveAllowed = false;
const held = new Set();  // arrow keys held
let padCommand = null;   // { x, yaw } while a pad button is held
let renewal = null;

const keyCommands = {
  ArrowUp: { x: 1, yaw: 0 }, ArrowDown: { x: -1, yaw: 0 }, ArrowLeft: { x: 0, yaw: 1 }, ArrowRight: { x: 0, yaw: -1 },
};

function wantedCommand() {
  if (padCommand) return padCommand;
  let x = 0, yaw = 0;
  for (const key of held) {
    x += keyCommands[key].x;
    yaw += keyCommands[key].yaw;
  }
  return { x: Math.sign(x), yaw: Math.sign(yaw) };
}

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function driveNow() {
  if (!driveAllowed) return;
  const command = wantedCommand();
  const moving = command.x !== 0 || command.yaw !== 0;
  send(moving ? { type: "drive", x: command.x, yaw: command.yaw } : { type: "stop" });
  document.getElementById("driving").textContent = moving ? `driving x ${command.x} yaw ${command.yaw}` : "stopped";
  if (moving && !renewal) renewal = setInterval(driveNow, 200);
  if (!moving && renewal) {
    clearInterval(renewal);
    renewal = null;
  }
}

function stopDriving() {
  held.clear();
  padCommand = null;
  driveNow();
}

window.addEventListener("keydown", (event) => {
  if (!driveAllowed || !(event.key in keyCommands)) return;
  event.preventDefault();
  if (held.has(event.key)) return;  // the keyboard's own repeat
  held.add(event.key);
  driveNow();
});
window.addEventListener("keyup", (event) => {
  if (!(event.key in keyCommands)) return;
  held.delete(event.key);
  driveNow();
});
window.addEventListener("blur", stopDriving);
document.addEventListener("visibilitychange", () => { if (document.hidden) stopDriving(); });
document.getElementById("motors-on").addEventListener("click", () => send({ type: "motors", on: true }));
document.getElementById("motors-off").addEventListener("click", () => {
  stopDriving();
  send({ type: "motors", on: false });
});
for (const button of document.querySelectorAll("#pad button[data-x]")) {
  button.addEventListener("pointerdown", () => {
    padCommand = { x: Number(button.dataset.x), yaw: Number(button.dataset.yaw) };
    driveNow();
  });
  for (const end of ["pointerup", "pointerleave", "pointercancel"]) button.addEventListener(end, stopDriving);
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.onopen = () => {
    statusLine.textContent = "connected";
    statusLine.className = "";
  };
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type === "hello") {
      driveAllowed = message.drive;
      document.getElementById("pad").style.display = driveAllowed ? "block" : "none";
    } else if (message.type === "map") {
      takeMap(message);
    } else if (message.type === "frame") {
      if (statusLine.className === "down") {
        statusLine.textContent = "connected";
        statusLine.className = "";
      }
      frame = message;
      showLegend();
    } else if (message.type === "lost") {
      // The tool lost the robot's server and is reconnecting; the last
      // frame stays on the canvas.
      const since = new Date(message.since * 1000).toLocaleTimeString();
      statusLine.textContent = `robot disconnected since ${since}: ${message.why}`;
      statusLine.className = "down";
    }
    draw();
  };
  socket.onclose = () => {
    if (renewal) clearInterval(renewal);
    renewal = null;
    held.clear();
    padCommand = null;
    statusLine.textContent = `disconnected since ${new Date().toLocaleTimeString()}`;
    statusLine.className = "down";
    setTimeout(connect, 2000);
  };
}

let drag = null;
canvas.addEventListener("mousedown", (event) => {
  drag = { x: event.clientX, y: event.clientY };
});
window.addEventListener("mouseup", () => { drag = null; });
window.addEventListener("mousemove", (event) => {
  if (!drag) return;
  follow.checked = false;
  centre.x -= (event.clientX - drag.x) / pixelsPerMetre;
  centre.y += (event.clientY - drag.y) / pixelsPerMetre;
  drag = { x: event.clientX, y: event.clientY };
  draw();
});
canvas.addEventListener("wheel", (event) => {
  event.preventDefault();
  pixelsPerMetre = Math.min(2000, Math.max(2, pixelsPerMetre * (event.deltaY < 0 ? 1.2 : 1 / 1.2)));
  draw();
}, { passive: false });
follow.addEventListener("change", draw);
window.addEventListener("resize", resize);
resize();
connect();
