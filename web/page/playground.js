// The playground's page: asks the WebAssembly module (in worker.js) for pictures and
// lists, and draws the pictures on the canvas at their natural size.
"use strict";

const $ = (id) => document.getElementById(id);
const canvas = $("picture");
const statusLine = $("status");
const params = new URLSearchParams(location.search);

// Two workers: one for quick lists, one for pictures, replaced when a newer picture is
// asked for while it is still drawing (so nothing waits behind a slow render).
const lists = new Worker("worker.js");
let painter = new Worker("worker.js");
let painting = false;
let asked = 0;

// Resolves with the answer; `partial` is called with each step's picture before it.
function ask(worker, request, partial) {
  return new Promise((resolve) => {
    const id = ++asked;
    const listen = (event) => {
      if (event.data.id !== id) return;
      if (event.data.partial) {
        if (partial) partial(event.data);
        return;
      }
      worker.removeEventListener("message", listen);
      resolve(event.data);
    };
    worker.addEventListener("message", listen);
    worker.postMessage({ id, request });
  });
}

function draw(reply) {
  canvas.width = reply.width;
  canvas.height = reply.height;
  canvas.getContext("2d").putImageData(new ImageData(reply.rgba, reply.width, reply.height), 0, 0);
}

function show(reply) {
  document.body.dataset.answers = Number(document.body.dataset.answers || 0) + 1;
  if (reply.status === 2) {
    statusLine.textContent = reply.text;
    statusLine.className = "error";
    document.body.dataset.state = "error";
    return;
  }
  statusLine.textContent = reply.text;
  statusLine.className = "";
  if (reply.status === 0) draw(reply);
  document.body.dataset.state = "drawn";
}

let latest = 0;
async function paint(request) {
  if (painting) {
    painter.terminate();
    painter = new Worker("worker.js");
  }
  const mine = ++latest;
  painting = true;
  document.body.dataset.state = "drawing";
  statusLine.textContent = "drawing…";
  const reply = await ask(painter, request, (step) => {
    if (mine !== latest) return;
    draw(step);
    statusLine.textContent = `drawing… ${step.text}`;
  });
  if (mine !== latest) return;
  painting = false;
  show(reply);
}

function request(command, fields, body) {
  const lines = [command];
  for (const [key, value] of Object.entries(fields)) {
    if (value !== undefined && value !== null && value !== "") lines.push(`${key}=${value}`);
  }
  return body === undefined ? lines.join("\n") : `${lines.join("\n")}\n\n${body}`;
}

// The gallery.
async function loadScenes() {
  const reply = await ask(lists, "scenes");
  for (const name of reply.text.split("\n")) {
    const option = document.createElement("option");
    option.textContent = name;
    $("scene").append(option);
  }
}
function drawScene(name) {
  return paint(request("scene", { name }));
}
$("draw-scene").onclick = () => drawScene($("scene").value);

// The L-system editor: every edit lists the file's systems again and draws the chosen one.
async function editorChanged() {
  const source = $("source").value;
  const reply = await ask(lists, request("systems", {}, source));
  const chosen = $("system").value || params.get("system") || "";
  const names = reply.text.split("\n").filter((line) => line && !line.startsWith("error: "));
  const broken = reply.text.split("\n").filter((line) => line.startsWith("error: "));
  $("system").replaceChildren(...names.map((name) => {
    const option = document.createElement("option");
    option.textContent = name;
    option.selected = name === chosen;
    return option;
  }));
  $("systems-error").textContent = broken.join("\n");
  return paint(request("lsystem", { system: $("system").value, order: $("order").value }, source));
}
let typing = null;
$("source").addEventListener("input", () => {
  clearTimeout(typing);
  typing = setTimeout(editorChanged, 250);
});
$("system").addEventListener("change", editorChanged);
// The angle field rewrites the chosen system's `Angle N` line in the text (so the
// reader's line and column still point into what is shown), then draws it.
$("angle").addEventListener("change", () => {
  const divisions = $("angle").value;
  const text = $("source").value;
  const name = $("system").value;
  if (!divisions || !name) return;
  const escaped = name.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
  const start = text.search(new RegExp(`^[ \t]*${escaped}[ \t]*\\{`, "mi"));
  if (start < 0) return;
  const close = text.indexOf("}", start);
  const end = close < 0 ? text.length : close;
  const block = text.slice(start, end);
  const line = /^([ \t]*)angle[ \t]+[^\s;]*/im;
  const changed = line.test(block)
    ? block.replace(line, `$1Angle ${divisions}`)
    : block.replace("{", `{\n  Angle ${divisions}`);
  $("source").value = text.slice(0, start) + changed + text.slice(end);
  document.body.dataset.mode = "lsystem";
  editorChanged();
});
$("file").addEventListener("change", async () => {
  const file = $("file").files[0];
  if (!file) return;
  $("source").value = await file.text();
  $("system").replaceChildren();
  document.body.dataset.mode = "lsystem";
  editorChanged();
});
$("order").addEventListener("change", editorChanged);

// Decimal numbers of any length, for zooms past a double's 16 digits: values are BigInt
// numerators over 10^DIGITS.
const DIGITS = 80n;
const SCALE = 10n ** DIGITS;
function parseDecimal(text) {
  const match = /^\s*([+-]?)(\d*)(?:\.(\d*))?(?:e([+-]?\d+))?\s*$/i.exec(text);
  if (!match) throw new Error(`not a number: ${text}`);
  const [, sign, whole, fraction = "", exponent = "0"] = match;
  const digits = BigInt((whole || "0") + fraction);
  const power = BigInt(exponent) - BigInt(fraction.length);
  let value = power >= 0n ? digits * 10n ** power * SCALE : (digits * SCALE) / 10n ** -power;
  return sign === "-" ? -value : value;
}
function formatDecimal(value) {
  const negative = value < 0n;
  const digits = (negative ? -value : value).toString().padStart(Number(DIGITS) + 1, "0");
  const whole = digits.slice(0, -Number(DIGITS));
  const fraction = digits.slice(-Number(DIGITS)).replace(/0+$/, "");
  return `${negative ? "-" : ""}${whole}${fraction ? "." + fraction : ""}`;
}

function escapeFields() {
  return {
    fractal: $("fractal").value,
    center: $("center").value,
    width: $("width").value,
    julia: $("fractal").value === "julia" ? $("julia").value : "",
    "max-iter": $("max-iter").value,
    palette: $("palette").value,
    precision: $("precision").value,
    steps: 1,
  };
}
function drawEscape() {
  return paint(request("escape", escapeFields()));
}
$("draw-escape").onclick = drawEscape;
canvas.addEventListener("click", (event) => {
  if (document.body.dataset.mode !== "escape") return;
  const bounds = canvas.getBoundingClientRect();
  const x = BigInt(Math.floor((event.clientX - bounds.left) * canvas.width / bounds.width));
  const y = BigInt(Math.floor((event.clientY - bounds.top) * canvas.height / bounds.height));
  const [re, im] = $("center").value.split(",").map(parseDecimal);
  const width = parseDecimal($("width").value);
  const w = BigInt(canvas.width), h = BigInt(canvas.height);
  // The pixel's middle: (2x + 1 − W)·width / 2W from the centre (rows down).
  const pointRe = re + (width * (2n * x + 1n - w)) / (2n * w);
  const pointIm = im - (width * (2n * y + 1n - h)) / (2n * w);
  const point = `${formatDecimal(pointRe)},${formatDecimal(pointIm)}`;
  if (event.altKey) {
    $("fractal").value = "julia";
    $("julia").value = point;
    $("center").value = "0,0";
    $("width").value = "3.2";
  } else {
    $("center").value = point;
    $("width").value = formatDecimal(event.shiftKey ? width * 2n : width / 2n);
  }
  drawEscape();
});
for (const id of ["draw-escape", "fractal", "palette", "precision", "max-iter"]) {
  $(id).addEventListener("change", () => { document.body.dataset.mode = "escape"; });
}
$("draw-escape").addEventListener("click", () => { document.body.dataset.mode = "escape"; });
$("draw-scene").addEventListener("click", () => { document.body.dataset.mode = "scene"; });
$("source").addEventListener("input", () => { document.body.dataset.mode = "lsystem"; });

// What the address asks: `?scene=NAME` (with `&embed=1`, the canvas alone at the top
// left), `?lsystem=TEXT[&system=NAME][&order=N]`, or an escape-time view by its fields.
async function start() {
  if (params.get("embed") === "1") document.body.classList.add("embed");
  const scenes = loadScenes();
  if (params.has("scene")) {
    document.body.dataset.mode = "scene";
    await scenes;
    $("scene").value = params.get("scene");
    return drawScene(params.get("scene"));
  }
  if (params.has("lsystem")) {
    document.body.dataset.mode = "lsystem";
    $("source").value = params.get("lsystem");
    if (params.has("order")) $("order").value = params.get("order");
    return editorChanged();
  }
  for (const key of ["fractal", "center", "width", "julia", "max-iter", "palette", "precision"]) {
    if (params.has(key)) $(key).value = params.get(key);
  }
  document.body.dataset.mode = "escape";
  return drawEscape();
}
start();
