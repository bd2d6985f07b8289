// lightpath serve: the page. Uses only the HTTP API of docs/serve.md; no library, nothing fetched
// from elsewhere.
"use strict";

const SVG = "http://www.w3.org/2000/svg";
// Path vertices and the segments leaving them, coloured by event (Heckbert's letters).
const EVENT_COLOURS = { E: "#ffffff", RD: "#4caf50", TD: "#4caf50", RG: "#ffc107", TG: "#ffc107",
  RS: "#29b6f6", TS: "#ab47bc", Rs: "#9e9e9e", Ts: "#9e9e9e", L: "#ff5722", O: "#ff9800", B: "#5c6bc0" };
const colourOf = (event) => EVENT_COLOURS[event] || "#e0e0e0";

const state = {
  scene: null,
  settings: null,        // the settings the server renders
  draft: null,           // what the controls say (sent after a short pause)
  generation: 0,
  passes: -1,
  layers: [],
  exposure: 0,
  explained: null,       // the last /api/explain answer
  pixel: null,
  selected: -1,          // index of the highlighted path group
  sendTimer: 0,
  sendSequence: 0,
  automatonGeneration: 0,
  latestGeneration: 0,   // the newest generation the server has told of (PUT answers, progress)
  started: new Map(),    // generation -> performance.now() when the page asked for it
  finished: new Map(),   // generation -> performance.now() when the page saw it done
  ticker: 0,             // redraws the status line each second while a pass is awaited
  lastProgress: null,
};

const $ = (id) => document.getElementById(id);

function element(tag, attributes = {}, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text) node.textContent = text;
  return node;
}

function svgElement(tag, attributes = {}) {
  const node = document.createElementNS(SVG, tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  return node;
}

async function getJson(url, options) {
  const response = await fetch(url, options);
  const body = await response.json();
  return { ok: response.ok, status: response.status, body };
}

// ---- settings: controls -> draft -> PUT /api/settings ----

function readControls() {
  const draft = structuredClone(state.draft);
  draft.integrator = $("integrator").value;
  draft.parameters = readParameterControls();
  draft.spp = Number($("spp").value);
  draft.width = Number($("width").value);
  draft.height = Number($("height").value);
  draft.maxDepth = Number($("max-depth").value);
  draft.lpes = [...document.querySelectorAll(".tile.aov")].map((tile) => ({
    name: tile.querySelector(".name").value,
    expression: tile.querySelector(".expression").value,
  }));
  return draft;
}

// The chosen integrator's own parameters, one control each, built from its schema
// (GET /api/scene's integratorParameters): empty means its default, so the server's schema decides
// type, range and default, and rejects what it must (shown as the request's error).
function buildParameterControls() {
  const schema = state.scene.integratorParameters[$("integrator").value] || [];
  const given = state.settings.parameters || {};
  $("integrator-parameters").replaceChildren(...schema.map((p) => {
    const attributes = { "data-parameter": p.name, "data-type": p.type, title: p.doc + (p.unit ? ` (${p.unit})` : "") };
    const words = p.type === "boolean" ? ["true", "false"] : p.choices;
    let input;
    if (words.length > 0) {
      input = element("select", attributes);
      input.append(element("option", { value: "" }, p.default ? `default (${p.default})` : "default"),
                   ...words.map((w) => element("option", { value: w }, w)));
    } else {
      const numeric = p.type === "number" || p.type === "integer";
      input = element("input", { ...attributes, type: numeric ? "number" : "text", placeholder: p.default || "default",
                                 ...(numeric ? { step: p.type === "integer" ? "1" : "any" } : {}),
                                 ...(numeric && p.low !== null ? { min: p.low } : {}),
                                 ...(numeric && p.high !== null ? { max: p.high } : {}) });
    }
    input.value = p.name in given ? String(given[p.name]) : "";
    input.addEventListener("change", scheduleSend);
    const label = element("label", {}, p.name + " ");
    label.append(input);
    return label;
  }));
}

function readParameterControls() {
  const parameters = {};
  for (const input of document.querySelectorAll("#integrator-parameters [data-parameter]")) {
    if (input.value === "") continue;
    const type = input.dataset.type;
    parameters[input.dataset.parameter] = type === "number" || type === "integer" ? Number(input.value)
                                        : type === "boolean" ? input.value === "true" : input.value;
  }
  return parameters;
}

function scheduleSend() {
  state.draft = readControls();
  clearTimeout(state.sendTimer);
  state.sendTimer = setTimeout(sendSettings, 250);
}

async function sendSettings() {
  const sequence = ++state.sendSequence;
  const askedAt = performance.now();
  const answer = await getJson("/api/settings", {
    method: "PUT", headers: { "Content-Type": "application/json" }, body: JSON.stringify(state.draft),
  });
  if (sequence !== state.sendSequence) return;  // a newer edit is on its way
  for (const tile of document.querySelectorAll(".tile.aov")) showTileError(tile, null);
  $("request-error").hidden = true;
  if (!answer.ok) {
    showRequestError(answer.body);
    markStaleTiles();
    return;
  }
  const namesChanged = JSON.stringify(answer.body.settings.lpes.map((e) => e.name)) !==
                       JSON.stringify(state.settings.lpes.map((e) => e.name));
  state.settings = answer.body.settings;
  if (!state.started.has(answer.body.generation)) state.started.set(answer.body.generation, askedAt);
  showWarnings(answer.body.warnings);
  showNotices(answer.body.notices || []);
  if (namesChanged) buildTiles(false);
  markStaleTiles();
  newGeneration(answer.body.generation);
}

// The server may take a value other than the one sent (the rasteriser's spp): say so.
function showNotices(notices) {
  $("notices").replaceChildren(...notices.map((n) => element("li", {}, "note: " + n)));
}

// A tile whose expression (or name) is not what the server renders keeps the image of the one
// before: marked, so it is never read as this expression's light.
function markStaleTiles() {
  document.querySelectorAll(".tile.aov").forEach((tile, i) => {
    const rendered = state.settings.lpes[i];
    const matches = rendered !== undefined && rendered.name === tile.querySelector(".name").value &&
                    rendered.expression === tile.querySelector(".expression").value;
    tile.classList.toggle("stale-image", !matches);
  });
}

// Anything the page shows of an older render (the explained pixel's table and drawn paths) is
// dropped as soon as a newer generation exists, and the pixel is explained again for it.
function newGeneration(generation) {
  if (generation <= state.latestGeneration) return;
  state.latestGeneration = generation;
  if (state.pixel && (!state.explained || state.explained.generation !== generation)) {
    clearExplanation();
    if (state.pixel) explain(...state.pixel);
  }
}

function clearExplanation() {
  state.explained = null;
  state.selected = -1;
  $("explain-table").tBodies[0].replaceChildren();
  delete $("explain-table").dataset.generation;
  $("sums-table").tBodies[0].replaceChildren();
  $("rejected").replaceChildren();
  $("copied").textContent = "";
  $("pixel-summary").textContent = "(explaining it again for the new render…)";
  $("overlay").replaceChildren();
  drawTopView();
  highlightAutomaton();
}

function showRequestError(error) {
  const match = /^lpes\[(\d+)\]/.exec(error.field || "");
  const tiles = document.querySelectorAll(".tile.aov");
  if (match && tiles[Number(match[1])]) {
    showTileError(tiles[Number(match[1])], error.error);
  } else {
    $("request-error").textContent = error.error;
    $("request-error").hidden = false;
  }
}

function showTileError(tile, message) {
  const pre = tile.querySelector("pre.error");
  pre.hidden = !message;
  pre.textContent = message || "";
  tile.classList.toggle("invalid", Boolean(message));
}

function showWarnings(warnings) {
  const list = $("warnings");
  list.replaceChildren(...warnings.map((w) => element("li", {}, "warning: " + w)));
  for (const tile of document.querySelectorAll(".tile.aov")) {
    const name = tile.querySelector(".name").value;
    // The command line's warnings name an AOV as "AOV name (...)" or "--lpe name: ...".
    const mine = warnings.filter((w) => w.startsWith(`AOV ${name} `) || w.startsWith(`--lpe ${name}:`));
    const line = tile.querySelector(".warning");
    line.textContent = mine.join(" ");
    line.hidden = mine.length === 0;
  }
}

// ---- tiles: beauty, one per AOV, rest ----

function imageUrl(layer) {
  return `/api/image/${encodeURIComponent(layer)}.png?exposure=${state.exposure}&generation=${state.generation}&pass=${state.passes}`;
}

function makeTile(kind, name, expression) {
  const tile = element("div", { class: "tile " + kind, "data-layer": name });
  const head = element("div", { class: "head" });
  if (kind === "aov") {
    const nameInput = element("input", { class: "name", value: name, spellcheck: "false", "aria-label": "AOV name" });
    // A textarea, so that the whole expression shows (wrapped, growing in height); one line only.
    const expressionInput = element("textarea", { class: "expression", rows: 1, spellcheck: "false", "aria-label": "light path expression" });
    expressionInput.value = expression;
    expressionInput.addEventListener("keydown", (event) => { if (event.key === "Enter") event.preventDefault(); });
    const remove = element("button", { type: "button", title: "remove this AOV" }, "×");
    nameInput.addEventListener("input", scheduleSend);
    expressionInput.addEventListener("input", () => {
      if (/[\r\n]/.test(expressionInput.value)) expressionInput.value = expressionInput.value.replace(/[\r\n]+/g, " ");
      scheduleSend();
    });
    remove.addEventListener("click", () => { tile.remove(); scheduleSend(); });
    head.append(nameInput, expressionInput, remove);
  } else {
    head.append(element("span", { class: "fixed" }, name),
                element("span", { class: "hint" }, kind === "beauty" ? " everything" : " light no AOV accepts"));
  }
  const png = element("a", { class: "png", href: `/api/image/${name}.png`, download: `${name}.png` }, "PNG");
  head.append(png);
  const image = element("img", { alt: name });
  const stale = element("div", { class: "stale" }, "not this expression's image: the server has not taken it");
  tile.append(head, stale, image, element("pre", { class: "error", hidden: "" }), element("div", { class: "warning", hidden: "" }));
  return tile;
}

function buildTiles(rebuildInputs = true) {
  const tiles = $("tiles");
  if (rebuildInputs) {
    tiles.replaceChildren(makeTile("beauty", "beauty"),
                          ...state.settings.lpes.map((e) => makeTile("aov", e.name, e.expression)),
                          makeTile("rest", "rest"));
  } else {
    // Keep the inputs being typed in; rename the layers their images come from.
    document.querySelectorAll(".tile.aov").forEach((tile, i) => {
      const name = state.settings.lpes[i] ? state.settings.lpes[i].name : tile.querySelector(".name").value;
      tile.dataset.layer = name;
      const png = tile.querySelector("a.png");
      png.href = `/api/image/${name}.png`;
      png.download = `${name}.png`;
    });
  }
  refreshImages();
}

function refreshImages() {
  if (state.passes < 1) return;
  const shown = new Set(state.layers);
  const load = (img, layer) => {
    if (!shown.has(layer)) return;
    const next = new Image();
    next.onload = () => { img.src = next.src; };
    next.onerror = () => {};  // superseded by a newer render: the next pass reloads it
    next.src = imageUrl(layer);
  };
  load($("beauty"), "beauty");
  for (const tile of document.querySelectorAll(".tile")) load(tile.querySelector("img"), tile.dataset.layer);
}

function applySettingsToControls() {
  const s = state.settings;
  $("integrator").value = s.integrator;
  buildParameterControls();
  $("spp").value = s.spp;
  $("width").value = s.width;
  $("height").value = s.height;
  $("max-depth").value = s.maxDepth;
  state.draft = structuredClone(s);
}

// ---- progress: long polls of /api/progress ----

// Seconds since the page asked for `p`'s generation (or, for one it did not ask for, since the
// server started preparing it): the preparation (radiosity's solve) is counted in it, as in the
// server's own two times.
function wallSeconds(p) {
  if (!state.started.has(p.generation))
    state.started.set(p.generation, performance.now() - 1000 * (p.seconds + p.preparation.seconds));
  if (p.done && !state.finished.has(p.generation)) state.finished.set(p.generation, performance.now());
  const end = state.finished.get(p.generation) ?? performance.now();
  return (end - state.started.get(p.generation)) / 1000;
}

function showStatus() {
  const p = state.lastProgress;
  if (!p) return;
  const s = p.settings;
  const wall = wallSeconds(p).toFixed(1);
  const timing = $("timing");
  timing.hidden = p.done;
  const preparation = p.preparation;
  if (p.passes === 0 && preparation.state === "running" && preparation.of > 0) {
    // A counted preprocess (radiosity's solve): the fraction of its steps done.
    timing.max = preparation.of;
    timing.value = preparation.steps;
    const percent = Math.floor(100 * preparation.steps / preparation.of);
    $("status").textContent = `preparing ${s.integrator}: ${percent}% (${preparation.steps} of ${preparation.of} steps)… ${wall} s`;
  } else if (p.passes === 0) {
    // The first pass has no fraction to show: an indeterminate bar and the seconds counting up.
    timing.removeAttribute("value");
    $("status").textContent = `preparing and rendering ${s.width}×${s.height} with ${s.integrator}… ${wall} s`;
  } else {
    timing.max = s.spp;
    timing.value = p.samples;
    const parts = preparation.seconds >= 0.005 ? `preparing ${preparation.seconds.toFixed(2)} s + ` : "";
    $("status").textContent = `${s.integrator}, ${s.width}×${s.height}: pass ${p.passes}, ${p.samples} spp of ${s.spp}` +
      `${p.done ? " (done)" : "…"} in ${wall} s (${parts}rendering ${p.seconds.toFixed(2)} s)`;
  }
  clearInterval(state.ticker);
  if (!p.done) state.ticker = setInterval(showStatus, 1000);
}

function showProgress(p) {
  const newer = p.generation !== state.generation || p.passes !== state.passes;
  state.generation = p.generation;
  state.passes = p.passes;
  state.layers = p.layers;
  state.lastProgress = p;
  $("stage").style.setProperty("--aspect", p.settings.width / p.settings.height);
  newGeneration(p.generation);
  showStatus();
  if (p.passes === 0) {
    $("sum-check").className = "";
    $("sum-check").textContent = "";
  } else {
    const ok = p.sumError <= 1e-4;
    $("sum-check").className = ok ? "ok" : "off";
    $("sum-check").textContent = ok
      ? `beauty = Σ AOVs + rest ✓ (largest difference ${p.sumError.toExponential(1)})`
      : `beauty ≠ Σ AOVs + rest: off by up to ${p.sumError.toFixed(4)} — the AOVs overlap and count some light twice`;
  }
  if (newer) {
    refreshImages();
    if (state.automatonGeneration !== p.generation) loadAutomaton();
  }
}

async function pollProgress() {
  for (;;) {
    try {
      // While the server prepares (a solve's steps count up without a pass), ask each second.
      const preparing = state.lastProgress && state.lastProgress.preparation.state !== "done";
      const url = `/api/progress?generation=${state.generation}&pass=${state.passes}&wait=${preparing ? 1 : 5}`;
      const answer = await getJson(url);
      if (answer.ok) showProgress(answer.body);
    } catch (error) {
      $("status").textContent = "the server does not answer (stopped?)";
      await new Promise((resolve) => setTimeout(resolve, 1000));
    }
  }
}

// ---- explain: table, paths over the image, top view, automaton ----

function groupContributions(contributions) {
  const groups = new Map();
  for (const c of contributions) {
    const g = groups.get(c.tuple);
    const strategy = c.strategy ? `(${c.strategy.s}, ${c.strategy.t})${c.strategy.splatted ? " splatted" : ""}` : null;
    if (g) {
      g.count += 1;
      for (let i = 0; i < 3; i++) g.rgb[i] += c.rgb[i];
      if (strategy && !g.strategies.includes(strategy)) g.strategies.push(strategy);
    } else {
      groups.set(c.tuple, { ...c, rgb: [...c.rgb], count: 1, strategies: strategy ? [strategy] : [] });
    }
  }
  // Largest first, as `lightpath explain` sorts them.
  const luminance = (rgb) => 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  return [...groups.values()].sort((a, b) => luminance(b.rgb) - luminance(a.rgb));
}

async function explain(x, y) {
  state.pixel = [x, y];
  const answer = await getJson(`/api/explain?x=${x}&y=${y}`);
  // 409: a newer explanation or a settings change replaced this one (docs/serve.md); its own
  // answer is on the way.
  if (answer.status === 409) return;
  if (!answer.ok) {
    showRequestError(answer.body);
    return;
  }
  // An answer for a render older than one the page knows of is stale already.
  if (answer.body.generation < state.latestGeneration) return;
  state.explained = answer.body;
  state.explained.groups = groupContributions(answer.body.contributions);
  state.pixel = [x, y];
  state.selected = -1;
  $("explain").hidden = false;
  $("pixel-label").textContent = `${x},${y}`;
  $("pixel-summary").textContent = `(${answer.body.integrator}, 1 sample through the pixel centre: ` +
    `${answer.body.contributions.length} contributions)`;
  drawExplanation();
}

// The product's factors joined by ×, then the values it is not multiplied by (the pdfs MIS weighs).
function formatFactors(factors) {
  const product = factors.filter((f) => f.inProduct !== false).map(formatFactor).join(" × ");
  const values = factors.filter((f) => f.inProduct === false).map(formatFactor).join(", ");
  return values ? `${product}; ${values}` : product;
}

function formatFactor(f) {
  const [r, g, b] = f.rgb.map((v) => Number(v.toPrecision(4)));
  return r === g && g === b ? `${f.name} ${r}` : `${f.name} (${r} ${g} ${b})`;
}

function formatRgb(rgb) { return rgb.map((v) => v.toFixed(6)).join(" "); }

function swatch(rgb) {
  const c = rgb.map((v) => Math.round(255 * Math.min(1, Math.max(0, v * 2 ** state.exposure)) ** (1 / 2.2)));
  return element("span", { class: "swatch", style: `background: rgb(${c.join(",")})` });
}

function drawExplanation() {
  const groups = state.explained.groups;
  const rows = groups.map((g, i) => {
    const row = element("tr", { "data-index": i });
    if (i === state.selected) row.classList.add("selected");
    const touched = g.vertices.slice(1).map((v) => v.touched).join(", ");
    const rgb = element("td", { class: "mono rgb" });
    rgb.append(swatch(g.rgb), formatRgb(g.rgb));
    row.append(element("td", {}, g.count > 1 ? `${i + 1} (×${g.count})` : `${i + 1}`),
               element("td", { class: "mono", title: g.tuple }, g.compact),
               element("td", { class: "mono strategy-col" }, g.strategies.join(", ")),
               element("td", { class: "mono lpe" }, g.lpe), element("td", {}, touched), rgb,
               element("td", {}, g.aovs.join(", ")),
               element("td", { class: "mono factors" }, formatFactors(g.factors)));
    row.addEventListener("click", () => selectPath(i));
    return row;
  });
  $("explain-table").tBodies[0].replaceChildren(...rows);
  $("explain-table").classList.toggle("no-strategy", !groups.some((g) => g.strategies.length > 0));
  $("explain-table").dataset.generation = state.explained.generation;
  $("sums-table").tBodies[0].replaceChildren(...state.explained.sums.map((s) => {
    const rgb = element("td", { class: "mono" });
    rgb.append(swatch(s.rgb), formatRgb(s.rgb));
    const row = element("tr");
    row.append(element("td", {}, s.layer), rgb, element("td", { class: "mono" }, s.expression));
    return row;
  }));
  $("rejected").replaceChildren(...state.explained.rejected.map((r) =>
    element("li", {}, `${r.lpe}: ${r.reason}`)));
  drawOverlay();
  drawTopView();
  highlightAutomaton();
}

function selectPath(index) {
  state.selected = state.selected === index ? -1 : index;
  if (state.selected >= 0) {
    const lpe = state.explained.groups[index].lpe;
    $("copied").textContent = `copied: ${lpe}`;
    if (navigator.clipboard) navigator.clipboard.writeText(lpe).catch(() => {});
  } else {
    $("copied").textContent = "";
  }
  drawExplanation();
}

function pathGroup(index, extraClass = "") {
  const g = svgElement("g", { class: "path " + extraClass, "data-index": index });
  if (state.selected >= 0) g.classList.add(index === state.selected ? "selected" : "dim");
  g.addEventListener("click", (event) => { event.stopPropagation(); selectPath(index); });
  return g;
}

function drawOverlay() {
  const overlay = $("overlay");
  const s = state.explained;
  const [width, height] = [state.settings.width, state.settings.height];
  overlay.setAttribute("viewBox", `0 0 ${width} ${height}`);
  const layers = [];
  const marker = svgElement("rect", { x: state.pixel[0], y: state.pixel[1], width: 1, height: 1, fill: "none",
                                      stroke: "#fff", "stroke-width": 2, "vector-effect": "non-scaling-stroke" });
  layers.push(marker);
  s.groups.forEach((path, index) => {
    const g = pathGroup(index);
    path.segments.forEach((segment, i) => {
      if (!segment) return;
      g.append(svgElement("line", { x1: segment[0], y1: segment[1], x2: segment[2], y2: segment[3],
                                    stroke: colourOf(path.vertices[i].event) }));
    });
    path.vertices.forEach((vertex) => {
      if (!vertex.pixel) return;
      g.append(svgElement("circle", { cx: vertex.pixel[0], cy: vertex.pixel[1], r: Math.max(width, height) / 160,
                                      fill: colourOf(vertex.event), "data-event": vertex.event }));
    });
    layers.push(g);
  });
  overlay.replaceChildren(...layers);
}

function drawTopView() {
  const view = $("top-view");
  const scene = state.scene;
  // The view frames the finite objects, the lights and the eye (x right, z down the page).
  let [x0, z0, x1, z1] = [Infinity, Infinity, -Infinity, -Infinity];
  const grow = (x, z) => { x0 = Math.min(x0, x); x1 = Math.max(x1, x); z0 = Math.min(z0, z); z1 = Math.max(z1, z); };
  for (const o of scene.objects) if (o.bounds) { grow(o.bounds[0][0], o.bounds[0][2]); grow(o.bounds[1][0], o.bounds[1][2]); }
  for (const l of scene.lights) grow(l.position[0], l.position[2]);
  grow(scene.camera.eye[0], scene.camera.eye[2]);
  for (const o of scene.objects) if (o.plane) grow(o.plane.point[0], o.plane.point[2]);
  const pad = 0.08 * Math.max(x1 - x0, z1 - z0, 1e-3);
  [x0, z0, x1, z1] = [x0 - pad, z0 - pad, x1 + pad, z1 + pad];
  const size = Math.max(x1 - x0, z1 - z0);
  view.setAttribute("viewBox", `${x0} ${z0} ${size} ${size}`);
  const stroke = size / 300;
  const items = [svgElement("rect", { x: x0, y: z0, width: size, height: size, fill: "#1e1e1c" })];
  for (const o of scene.objects) {
    if (o.plane) {
      const [nx, , nz] = o.plane.normal;
      if (Math.hypot(nx, nz) < 0.5) continue;  // floors and ceilings are seen face on
      const [px, , pz] = o.plane.point;
      const [dx, dz] = [-nz, nx];
      items.push(svgElement("line", { x1: px - 1e3 * dx, y1: pz - 1e3 * dz, x2: px + 1e3 * dx, y2: pz + 1e3 * dz,
                                      stroke: "#888", "stroke-width": stroke * 2 }));
    } else if (o.bounds) {
      const [a, b] = o.bounds;
      const rect = svgElement("rect", { x: a[0], y: a[2], width: Math.max(b[0] - a[0], stroke), height: Math.max(b[2] - a[2], stroke),
                                        fill: o.emissive ? "#5a4a1a" : "#3a3a36", stroke: "#aaa", "stroke-width": stroke });
      const title = svgElement("title");
      title.textContent = o.name || o.label;
      rect.append(title);
      items.push(rect);
    }
  }
  for (const l of scene.lights)
    items.push(svgElement("circle", { cx: l.position[0], cy: l.position[2], r: stroke * 5, fill: colourOf("L") }));
  const [ex, , ez] = scene.camera.eye;
  items.push(svgElement("circle", { cx: ex, cy: ez, r: stroke * 5, fill: "#fff" }));
  if (state.explained) {
    state.explained.groups.forEach((path, index) => {
      const g = pathGroup(index);
      const vertices = path.vertices;
      for (let i = 0; i + 1 < vertices.length; i++) {
        const [a, b] = [vertices[i].position, vertices[i + 1].position];
        if (!a || !b) continue;
        g.append(svgElement("line", { x1: a[0], y1: a[2], x2: b[0], y2: b[2], stroke: colourOf(vertices[i].event) }));
      }
      for (const v of vertices)
        if (v.position) g.append(svgElement("circle", { cx: v.position[0], cy: v.position[2], r: stroke * 3, fill: colourOf(v.event) }));
      items.push(g);
    });
  }
  view.replaceChildren(...items);
}

async function loadAutomaton() {
  const generation = state.generation;
  const response = await fetch(`/api/automaton.svg?generation=${generation}`);
  if (!response.ok) {
    $("automaton").textContent = (await response.json()).error;
    return;
  }
  const text = await response.text();
  const svg = new DOMParser().parseFromString(text, "image/svg+xml").documentElement;
  $("automaton").replaceChildren(document.importNode(svg, true));
  state.automatonGeneration = generation;
  highlightAutomaton();
}

function highlightAutomaton() {
  const groups = state.explained ? state.explained.groups : [];
  const visited = new Set(groups.flatMap((g) => g.states));
  const onPath = new Set(state.selected >= 0 ? groups[state.selected].states : []);
  for (const node of document.querySelectorAll("#automaton g.node")) {
    const title = node.querySelector("title");
    const id = title ? Number(title.textContent) : NaN;
    node.classList.toggle("visited", visited.has(id));
    node.classList.toggle("on-path", onPath.has(id));
  }
}

// ---- start ----

function pixelOf(event) {
  const image = $("beauty");
  const box = image.getBoundingClientRect();
  const x = Math.floor((event.clientX - box.left) / box.width * state.settings.width);
  const y = Math.floor((event.clientY - box.top) / box.height * state.settings.height);
  return [Math.min(Math.max(x, 0), state.settings.width - 1), Math.min(Math.max(y, 0), state.settings.height - 1)];
}

async function start() {
  const scene = await getJson("/api/scene");
  state.scene = scene.body;
  $("scene-name").textContent = state.scene.scene;
  document.title = `lightpath serve: ${state.scene.scene}`;
  $("integrator").replaceChildren(...state.scene.integrators.map((name) => element("option", { value: name }, name)));
  $("spp").max = state.scene.limits.spp;
  $("width").max = $("height").max = state.scene.limits.side;
  for (const preset of state.scene.presets) {
    const button = element("button", { type: "button", "data-preset": preset.name }, preset.name);
    button.addEventListener("click", () => {
      state.settings = { ...state.settings, lpes: preset.lpes };
      state.draft = { ...readControls(), lpes: preset.lpes };
      buildTiles(true);
      scheduleSendNow();
    });
    $("presets").append(button);
  }
  const current = await getJson("/api/settings");
  state.settings = current.body.settings;
  applySettingsToControls();
  buildTiles(true);
  showWarnings(current.body.warnings);
  state.latestGeneration = current.body.generation;
  $("integrator").addEventListener("change", buildParameterControls);
  for (const id of ["integrator", "spp", "width", "height", "max-depth"]) $(id).addEventListener("change", scheduleSend);
  $("exposure").addEventListener("input", () => {
    state.exposure = Number($("exposure").value);
    $("exposure-value").textContent = state.exposure;
    refreshImages();
  });
  $("add-lpe").addEventListener("click", () => {
    const used = new Set([...document.querySelectorAll(".tile.aov .name")].map((n) => n.value));
    let n = 1;
    while (used.has(`aov${n}`)) n++;
    $("tiles").insertBefore(makeTile("aov", `aov${n}`, "E.*L"), document.querySelector(".tile.rest"));
    scheduleSend();
  });
  $("stage").addEventListener("click", (event) => {
    const [x, y] = pixelOf(event);
    explain(x, y);
  });
  pollProgress();
}

function scheduleSendNow() {
  clearTimeout(state.sendTimer);
  sendSettings();
}

start();
