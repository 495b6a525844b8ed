// The polygon builder's browser side (anywidget ES module; no imports, nothing fetched).
//
// It draws the linkage to scale and the polygon canvas with its stated scale, and turns
// pointer input (mouse, touchpad, touch: pointer events) or typed input into steps of the
// construction, which it hands to Python (the `steps` trait). It judges nothing: Python
// checks each step with the package's rules and sends back `verdicts`, `summary`, `hint`.
// Coordinates in `steps` are SI; the canvas works in the phase's display unit.

const SVG = "http://www.w3.org/2000/svg";
const COLOURS = {
  normal: "#0072B2", tangential: "#D55E00", coriolis: "#009E73", slip: "#CC79A7",
  resultant: "#000000", velocity: "#E69F00", known: "#555555",
};
const DASH = {
  normal: "", tangential: "7 3.5", coriolis: "8 3 2 3", slip: "2 2.5",
  resultant: "", velocity: "", known: "",
};
const WIDTH = { resultant: 2.8, coriolis: 2.2, slip: 2.4 };
const WRONG = "#c0142b";
const SNAP_DEG = 2.5;

function h(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "text") e.textContent = v;
    else if (k === "html") e.innerHTML = v;
    else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of [].concat(children)) if (c != null) e.append(c);
  return e;
}

function s(tag, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.append(e);
  return e;
}

function esc(text) {
  return String(text).replace(/[&<>"']/g, (c) => ({
    "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;",
  })[c]);
}

const GREEK = { omega: "\u03c9", alpha: "\u03b1", gamma: "\u03b3", theta: "\u03b8" };

// A step name or a message in the chapter's notation, as HTML (escaped first).
function rich(text) {
  let t = esc(text);
  t = t.replace(/\b([AV])_([A-Za-z0-9]+)(?:\^([a-z]+))?/g, (m, v, sub, sup) => {
    const su = sub.replace(/^([A-Z])(\d)$/, "$1<sub>$2</sub>");
    return `<b>${v}</b><sub>${su}</sub>` + (sup ? `<sup>${sup}</sup>` : "");
  });
  t = t.replace(/\b(omega|alpha|gamma|theta)(\d?)(\^2)?/g, (m, g, d, sq) =>
    `${GREEK[g]}<sub>${d}</sub>` + (sq ? "<sup>2</sup>" : ""));
  t = t.replace(/\bO(\d)/g, "O<sub>$1</sub>");
  t = t.replace(/\^2\b/g, "<sup>2</sup>");
  return t;
}

function fmt(x) {
  if (!isFinite(x)) return "-";
  const a = Math.abs(x);
  if (a !== 0 && (a < 1e-3 || a >= 1e6)) return x.toExponential(3);
  return String(Number(x.toPrecision(4)));
}

function unitText(u) {
  return esc(u).replace(/\^2/g, "<sup>2</sup>");
}

// a unit as plain text (an <option> holds no markup)
function unitPlain(u) {
  return String(u).replace(/\^2/g, "\u00b2");
}

function angleOf(x, y) {
  let a = (Math.atan2(y, x) * 180) / Math.PI;
  return a < 0 ? a + 360 : a;
}

function wrap180(d) {
  d = ((d + 180) % 360 + 360) % 360 - 180;
  return d;
}

function crossing(p1, u1, p2, u2) {
  const den = u1[0] * u2[1] - u1[1] * u2[0];
  if (Math.abs(den) < 1e-9) return null;
  const w = [p2[0] - p1[0], p2[1] - p1[1]];
  const t = (w[0] * u2[1] - w[1] * u2[0]) / den;
  return [p1[0] + t * u1[0], p1[1] + t * u1[1]];
}

function dirOf(deg) {
  const r = (deg * Math.PI) / 180;
  return [Math.cos(r), Math.sin(r)];
}

function render({ model, el }) {
  const P = model.get("problem");
  const root = h("div", { class: "apb", "data-testid": "polygon-builder" });
  el.append(root);
  const state = {
    phase: P.phases[0].id,
    tool: "vector",
    views: {},
    history: [],
    drag: null,
    pointers: new Map(),
    pinch: null,
    ghost: null,
    selected: null,
    snapDir: true,
    clearArmed: false,
    message: null,
  };
  const phaseOf = (id) => P.phases.find((p) => p.id === id);

  // ---------------------------------------------------------------- layout
  const header = h("div", { class: "apb-head" }, [
    h("div", { class: "apb-title", text: P.title || "Polygon builder" }),
    h("div", {
      class: "apb-note",
      html:
        (P.mode === "practice"
          ? "<b>Practice</b>: each step is checked as you make it"
          : "<b>Assignment</b>: your construction is saved with the notebook and judged when " +
            "the assignment is graded (save the notebook before you submit)") +
        `. Directions are right within ${P.band}\u00b0, lengths within ${P.tol_pct}% of the ` +
        "polygon's largest vector.",
    }),
  ]);
  const tabs = h("div", { class: "apb-tabs", role: "tablist" });
  const linkSvg = s("svg", { class: "apb-linkage", "data-testid": "linkage" });
  const given = h("div", { class: "apb-given" });
  const canvas = s("svg", { class: "apb-canvas", "data-testid": "canvas" });
  const zoomBar = h("div", { class: "apb-zoom" }, [
    h("button", { type: "button", "aria-label": "Zoom in", title: "Zoom in (or Ctrl + wheel, or a pinch)", "data-testid": "zoom-in",
      text: "+", onclick: () => zoomBy(1.25) }),
    h("button", { type: "button", "aria-label": "Zoom out", "data-testid": "zoom-out",
      text: "\u2212", onclick: () => zoomBy(0.8) }),
    h("button", { type: "button", "aria-label": "Fit the drawing", "data-testid": "zoom-fit",
      text: "fit", onclick: () => fit(true) }),
  ]);
  const readout = h("div", { class: "apb-readout", "data-testid": "readout", "aria-live": "polite" });
  const scaleNote = h("div", { class: "apb-scale", "data-testid": "scale" });
  const canvasBox = h("div", { class: "apb-canvas-box" }, [canvas, zoomBar, scaleNote, readout]);
  const linkBox = h("div", { class: "apb-link-box" }, [linkSvg, given]);
  const main = h("div", { class: "apb-main" }, [linkBox, canvasBox]);
  const tools = h("div", { class: "apb-tools", role: "toolbar" });
  const panel = h("div", { class: "apb-panel", "data-testid": "panel" });
  const feedback = h("div", { class: "apb-feedback" });
  const message = h("div", { class: "apb-message", "data-testid": "message", "aria-live": "polite" });
  const summary = h("div", { class: "apb-summary", "data-testid": "summary" });
  const list = h("ol", { class: "apb-steps", "data-testid": "steps" });
  feedback.append(summary, list);
  root.append(header, tabs, main, message, tools, panel, feedback);

  // ---------------------------------------------------------------- data helpers
  const steps = () => model.get("steps") || [];
  const phaseSteps = () => steps().map((st, i) => [st, i]).filter(([st]) => st.phase === state.phase);
  const keyOf = (st) => (st.op === "point" ? "point:X" : `${st.op}:${st.name}`);

  // the verdicts on screen are those of the steps on screen: none while Python judges a change
  const verdictsNow = () => (state.pending ? [] : model.get("verdicts") || []);

  function commit(next) {
    state.history.push(steps());
    if (state.history.length > 200) state.history.shift();
    state.pending = true;
    model.set("steps", next);
    model.save_changes();
  }

  function addStep(st) {
    const key = keyOf(st);
    const next = steps().filter((o) => !(o.phase === st.phase && keyOf(o) === key));
    next.push(st);
    state.ghost = null;
    commit(next);
  }

  function removeStep(index) {
    const next = steps().slice();
    next.splice(index, 1);
    commit(next);
  }

  function undo() {
    if (!state.history.length) return;
    state.pending = true;
    model.set("steps", state.history.pop());
    model.save_changes();
    say("The last step is undone.", null);
  }

  function clearPhase() {
    if (!state.clearArmed) {
      state.clearArmed = true;
      buildTools();
      setTimeout(() => { state.clearArmed = false; buildTools(); }, 4000);
      return;
    }
    state.clearArmed = false;
    commit(steps().filter((st) => st.phase !== state.phase));
  }

  // ---------------------------------------------------------------- view (display units)
  function size() {
    const r = canvas.getBoundingClientRect();
    return [Math.max(r.width, 50), Math.max(r.height, 50)];
  }

  function view() {
    if (!state.views[state.phase]) {
      const ph = phaseOf(state.phase);
      const [W, H] = size();
      state.views[state.phase] = { cx: 0, cy: 0, z: Math.min(W, H) / (17 * ph.scale) };
    }
    return state.views[state.phase];
  }

  const toScreen = (x, y) => {
    const v = view();
    const [W, H] = size();
    return [W / 2 + (x - v.cx) * v.z, H / 2 - (y - v.cy) * v.z];
  };
  const toWorld = (sx, sy) => {
    const v = view();
    const [W, H] = size();
    return [v.cx + (sx - W / 2) / v.z, v.cy - (sy - H / 2) / v.z];
  };
  const factor = () => phaseOf(state.phase).factor;
  const disp = (p) => [p[0] * factor(), p[1] * factor()];
  const si = (p) => [p[0] / factor(), p[1] / factor()];

  function zoomBy(k, sx, sy) {
    const v = view();
    const [W, H] = size();
    sx = sx ?? W / 2;
    sy = sy ?? H / 2;
    const before = toWorld(sx, sy);
    v.z = Math.min(Math.max(v.z * k, 1e-9), 1e12);
    const after = toWorld(sx, sy);
    v.cx += before[0] - after[0];
    v.cy += before[1] - after[1];
    drawCanvas();
  }

  function fit(all) {
    const ph = phaseOf(state.phase);
    let pts = [[0, 0]];
    for (const [st] of phaseSteps()) {
      for (const k of ["tail", "tip", "through", "at"]) if (st[k]) pts.push(disp(st[k]));
    }
    if (state.ghost && state.ghost.phase === state.phase && state.ghost.ghost) {
      const g = state.ghost.ghost;
      for (const k of ["tail", "tip", "through", "at"]) if (g[k]) pts.push(disp(g[k]));
    }
    const xs = pts.map((p) => p[0]);
    const ys = pts.map((p) => p[1]);
    const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys),
      4 * ph.scale);
    const [W, H] = size();
    const v = view();
    v.cx = (Math.max(...xs) + Math.min(...xs)) / 2;
    v.cy = (Math.max(...ys) + Math.min(...ys)) / 2;
    v.z = (Math.min(W, H) * 0.8) / span;
    if (all) drawCanvas();
  }

  // ---------------------------------------------------------------- snapping
  function snapPoints() {
    const out = [{ p: [0, 0], label: "the pole" }];
    for (const [st] of phaseSteps()) {
      if (st.op === "vector") {
        out.push({ p: disp(st.tip), label: `the tip of ${st.name}` });
        out.push({ p: disp(st.tail), label: `the tail of ${st.name}` });
      } else if (st.op === "point") {
        out.push({ p: disp(st.at), label: "the point where the lines cross" });
      } else if (st.op === "line") {
        out.push({ p: disp(st.through), label: `the point the line of ${st.name} passes through` });
      }
    }
    const seen = [];
    return out.filter((q) => {
      if (seen.some((o) => Math.hypot(o.p[0] - q.p[0], o.p[1] - q.p[1]) < 1e-12)) return false;
      seen.push(q);
      return true;
    });
  }

  function nearestSnap(sx, sy, radius) {
    let best = null;
    for (const q of snapPoints()) {
      const [qx, qy] = toScreen(q.p[0], q.p[1]);
      const d = Math.hypot(qx - sx, qy - sy);
      if (d <= radius && (!best || d < best.d)) best = { ...q, d };
    }
    return best;
  }

  function directionChoices() {
    const out = [];
    for (const d of P.directions) {
      out.push({ angle: d.angle, text: `\u2225 ${d.label}` });
      out.push({ angle: d.angle + 180, text: `\u2225 ${d.label}` });
      out.push({ angle: d.angle + 90, text: `\u27c2 ${d.label}` });
      out.push({ angle: d.angle - 90, text: `\u27c2 ${d.label}` });
    }
    return out;
  }

  function snapDirection(deg) {
    if (!state.snapDir) return null;
    let best = null;
    for (const c of directionChoices()) {
      const d = Math.abs(wrap180(deg - c.angle));
      if (d <= SNAP_DEG && (!best || d < best.d)) best = { ...c, d };
    }
    return best;
  }

  // ---------------------------------------------------------------- drawing helpers
  function label(parent, name, x, y, colour) {
    const t = s("text", { x, y, class: "apb-label", fill: colour || "#111" }, parent);
    const m = name.match(/^([AV])_([A-Za-z0-9]+)(?:\^([a-z]+))?$/);
    if (!m) {
      t.textContent = name;
      return t;
    }
    const b = s("tspan", { "font-weight": "bold" }, t);
    b.textContent = m[1];
    const sub = s("tspan", { dy: "4", "font-size": "75%" }, t);
    sub.textContent = m[2];
    if (m[3]) {
      const sup = s("tspan", { dy: "-10", "font-size": "75%" }, t);
      sup.textContent = m[3];
    }
    return t;
  }

  function arrow(parent, a, b, kind, opts = {}) {
    const [x1, y1] = toScreen(a[0], a[1]);
    const [x2, y2] = toScreen(b[0], b[1]);
    const len = Math.hypot(x2 - x1, y2 - y1);
    const colour = opts.colour || COLOURS[kind] || "#333";
    const g = s("g", { class: opts.cls || "apb-vector" }, parent);
    if (len < 0.5) return g;
    const ux = (x2 - x1) / len;
    const uy = (y2 - y1) / len;
    const head = Math.min(11, len * 0.45);
    s("line", {
      x1, y1, x2: x2 - ux * head * 0.8, y2: y2 - uy * head * 0.8,
      stroke: colour, "stroke-width": opts.width || WIDTH[kind] || 1.9,
      "stroke-dasharray": opts.dash ?? DASH[kind] ?? "", "stroke-linecap": "round",
    }, g);
    const px = -uy;
    const py = ux;
    s("polygon", {
      points: `${x2},${y2} ${x2 - ux * head + px * head * 0.38},${y2 - uy * head + py * head * 0.38} ` +
        `${x2 - ux * head - px * head * 0.38},${y2 - uy * head - py * head * 0.38}`,
      fill: colour,
    }, g);
    return g;
  }

  function clipLine(p, u, W, H) {
    // screen-space line through p (screen) along u (screen), clipped to the box
    const ts = [];
    const pushIf = (t) => {
      const x = p[0] + t * u[0];
      const y = p[1] + t * u[1];
      if (x >= -1 && x <= W + 1 && y >= -1 && y <= H + 1) ts.push(t);
    };
    if (Math.abs(u[0]) > 1e-12) { pushIf(-p[0] / u[0]); pushIf((W - p[0]) / u[0]); }
    if (Math.abs(u[1]) > 1e-12) { pushIf(-p[1] / u[1]); pushIf((H - p[1]) / u[1]); }
    if (ts.length < 2) return null;
    const a = Math.min(...ts);
    const b = Math.max(...ts);
    return [p[0] + a * u[0], p[1] + a * u[1], p[0] + b * u[0], p[1] + b * u[1]];
  }

  function drawLine(parent, through, angle, opts = {}) {
    const [W, H] = size();
    const p = toScreen(through[0], through[1]);
    const d = dirOf(angle);
    const seg = clipLine(p, [d[0], -d[1]], W, H);
    if (!seg) return null;
    return s("line", {
      x1: seg[0], y1: seg[1], x2: seg[2], y2: seg[3],
      stroke: opts.colour || "#8c8c8c", "stroke-width": opts.width || 1.2,
      "stroke-dasharray": opts.dash || "9 5", class: opts.cls || "apb-line",
    }, parent);
  }

  function badge(parent, x, y, text) {
    const g = s("g", { class: "apb-badge" }, parent);
    s("circle", { cx: x, cy: y, r: 9, fill: WRONG }, g);
    const t = s("text", { x, y: y + 4, "text-anchor": "middle", fill: "#fff",
      "font-size": "11", "font-weight": "bold" }, g);
    t.textContent = text;
  }

  // ---------------------------------------------------------------- the canvas
  function drawCanvas() {
    const ph = phaseOf(state.phase);
    const [W, H] = size();
    const v = view();
    canvas.setAttribute("viewBox", `0 0 ${W} ${H}`);
    canvas.dataset.view = JSON.stringify({ cx: v.cx, cy: v.cy, z: v.z, factor: ph.factor });
    canvas.replaceChildren();
    // grid: one square = ph.scale display units
    const g = s("g", { class: "apb-grid" }, canvas);
    let step = ph.scale;
    while (step * v.z < 8) step *= 5;
    const [x0, y1] = toWorld(0, 0);
    const [x1, y0] = toWorld(W, H);
    for (let k = Math.ceil(x0 / step); k * step <= x1; k++) {
      const [sx] = toScreen(k * step, 0);
      s("line", { x1: sx, y1: 0, x2: sx, y2: H, class: k % 5 ? "minor" : "major" }, g);
    }
    for (let k = Math.ceil(y0 / step); k * step <= y1; k++) {
      const [, sy] = toScreen(0, k * step);
      s("line", { x1: 0, y1: sy, x2: W, y2: sy, class: k % 5 ? "minor" : "major" }, g);
    }
    scaleNote.innerHTML = `1 square = ${fmt(step)} ${unitText(ph.unit)}` +
      (step !== ph.scale ? " (zoomed out)" : "");
    const verdicts = verdictsNow();
    const layer = s("g", {}, canvas);
    const marks = s("g", {}, canvas);
    let n = 0;
    const numbers = {};
    for (const [st, i] of phaseSteps()) numbers[i] = ++n;
    // lines first, then vectors, points
    for (const [st, i] of phaseSteps()) {
      if (st.op !== "line") continue;
      const bad = verdicts[i] && verdicts[i].ok === false && P.mode === "practice";
      const ln = drawLine(layer, disp(st.through), st.angle, bad ? { colour: WRONG, width: 1.8 } : {});
      if (ln) ln.dataset.step = String(i);
      const [bx, by] = toScreen(...disp(st.through));
      if (bad) badge(marks, bx + 12, by - 12, numbers[i]);
    }
    // labels go on the side of each vector away from the drawing's middle
    let mx = 0;
    let my = 0;
    let count = 0;
    for (const [st] of phaseSteps()) {
      for (const k of ["tail", "tip", "at"]) {
        if (!st[k]) continue;
        const [qx, qy] = toScreen(...disp(st[k]));
        mx += qx;
        my += qy;
        count += 1;
      }
    }
    if (count) { mx /= count; my /= count; }
    for (const [st, i] of phaseSteps()) {
      if (st.op !== "vector") continue;
      const kind = (ph.vectors.find((x) => x.name === st.name) || {}).kind || "known";
      const bad = verdicts[i] && verdicts[i].ok === false && P.mode === "practice";
      const sel = state.selected === i;
      const gv = arrow(layer, disp(st.tail), disp(st.tip), kind,
        bad ? { colour: WRONG } : sel ? { width: 3.4 } : {});
      gv.dataset.step = String(i);
      const [ax, ay] = toScreen(...disp(st.tail));
      const [bx, by] = toScreen(...disp(st.tip));
      const len = Math.hypot(bx - ax, by - ay) || 1;
      let nx = -(by - ay) / len;
      let ny = (bx - ax) / len;
      if (nx * ((ax + bx) / 2 - mx) + ny * ((ay + by) / 2 - my) < 0) { nx = -nx; ny = -ny; }
      const lt = label(layer, st.name, (ax + bx) / 2 + nx * 16, (ay + by) / 2 + ny * 16 + 5,
        bad ? WRONG : null);
      lt.setAttribute("text-anchor", "middle");
      if (bad) badge(marks, (ax + bx) / 2 - nx * 14, (ay + by) / 2 - ny * 14, numbers[i]);
    }
    for (const [st, i] of phaseSteps()) {
      if (st.op !== "point") continue;
      const bad = verdicts[i] && verdicts[i].ok === false && P.mode === "practice";
      const [px, py] = toScreen(...disp(st.at));
      const c = s("circle", { cx: px, cy: py, r: 6, class: "apb-point",
        stroke: bad ? WRONG : "#000" }, layer);
      c.dataset.step = String(i);
      if (bad) badge(marks, px + 13, py - 13, numbers[i]);
    }
    // the pole
    const [ox, oy] = toScreen(0, 0);
    s("circle", { cx: ox, cy: oy, r: 5, class: "apb-pole", "data-testid": "pole" }, canvas);
    const pl = s("text", { x: ox - 8, y: oy + 17, class: "apb-small", "text-anchor": "end" }, canvas);
    pl.textContent = "pole";
    // the step shown on request
    const gh = state.ghost;
    if (gh && gh.phase === state.phase && gh.ghost) {
      const gg = s("g", { class: "apb-ghost", "data-testid": "ghost" }, canvas);
      const k = gh.ghost;
      if (k.op === "vector") arrow(gg, disp(k.tail), disp(k.tip), "known",
        { colour: "#6a3d9a", dash: "3 3", width: 2 });
      if (k.op === "line") drawLine(gg, disp(k.through), k.angle, { colour: "#6a3d9a", dash: "3 3" });
      if (k.op === "point") {
        const [gx, gy] = toScreen(...disp(k.at));
        s("circle", { cx: gx, cy: gy, r: 8, fill: "none", stroke: "#6a3d9a",
          "stroke-dasharray": "3 3", "stroke-width": 2 }, gg);
      }
    }
    // what is being drawn
    const d = state.drag;
    if (d && d.kind !== "pan" && d.to) {
      const pv = s("g", { class: "apb-preview" }, canvas);
      if (d.kind === "vector") {
        const kind = (ph.vectors.find((x) => x.name === d.name) || {}).kind || "known";
        arrow(pv, d.from, d.to, kind);
      } else if (d.kind === "line") {
        drawLine(pv, d.from, angleOf(d.to[0] - d.from[0], d.to[1] - d.from[1]),
          { colour: "#444", dash: "5 4" });
      }
    }
  }

  // ---------------------------------------------------------------- pointer input
  function local(ev) {
    const r = canvas.getBoundingClientRect();
    return [ev.clientX - r.left, ev.clientY - r.top];
  }

  function describeDrag(d) {
    const ph = phaseOf(state.phase);
    const dx = d.to[0] - d.from[0];
    const dy = d.to[1] - d.from[1];
    const len = Math.hypot(dx, dy);
    const ang = angleOf(dx, dy);
    const snapped = d.snapped ? ` (${esc(d.snapped)})` : "";
    if (d.kind === "vector") {
      readout.innerHTML = `${rich(d.name)}: ${fmt(len)} ${unitText(ph.unit)} = ` +
        `${fmt(len / ph.scale)} squares, at ${fmt(ang)}\u00b0${snapped}`;
    } else {
      readout.innerHTML = `line of ${rich(d.name)} at ${fmt(ang % 180)}\u00b0${snapped}`;
    }
  }

  canvas.addEventListener("pointerdown", (ev) => {
    if (ev.button !== undefined && ev.button > 0) return;
    ev.preventDefault();
    canvas.setPointerCapture(ev.pointerId);
    const p = local(ev);
    state.pointers.set(ev.pointerId, p);
    if (state.pointers.size === 2) {
      const [a, b] = [...state.pointers.values()];
      state.pinch = { dist: Math.hypot(a[0] - b[0], a[1] - b[1]), mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] };
      state.drag = null;
      drawCanvas();
      return;
    }
    const radius = ev.pointerType === "touch" ? 26 : 14;
    const snap = nearestSnap(p[0], p[1], radius);
    const world = snap ? snap.p : toWorld(p[0], p[1]);
    if (state.tool === "vector" || state.tool === "line") {
      const name = state.tool === "vector" ? vectorName.value : lineName.value;
      state.drag = { kind: state.tool, name, from: world, to: null, snapFrom: snap, id: ev.pointerId };
    } else if (state.tool === "pan") {
      state.drag = { kind: "pan", last: p, id: ev.pointerId };
    } else {
      state.drag = { kind: "tap", at: p, id: ev.pointerId };
    }
  });

  canvas.addEventListener("pointermove", (ev) => {
    if (!state.pointers.has(ev.pointerId)) return;
    const p = local(ev);
    state.pointers.set(ev.pointerId, p);
    if (state.pinch && state.pointers.size === 2) {
      const [a, b] = [...state.pointers.values()];
      const dist = Math.hypot(a[0] - b[0], a[1] - b[1]);
      const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      const v = view();
      v.cx -= (mid[0] - state.pinch.mid[0]) / v.z;
      v.cy += (mid[1] - state.pinch.mid[1]) / v.z;
      if (state.pinch.dist > 0) zoomBy(dist / state.pinch.dist, mid[0], mid[1]);
      state.pinch = { dist, mid };
      return;
    }
    const d = state.drag;
    if (!d || d.id !== ev.pointerId) return;
    if (d.kind === "pan") {
      const v = view();
      v.cx -= (p[0] - d.last[0]) / v.z;
      v.cy += (p[1] - d.last[1]) / v.z;
      d.last = p;
      drawCanvas();
      return;
    }
    if (d.kind !== "vector" && d.kind !== "line") return;
    let to = toWorld(p[0], p[1]);
    d.snapped = null;
    const radius = ev.pointerType === "touch" ? 26 : 14;
    const tipSnap = d.kind === "vector" ? nearestSnap(p[0], p[1], radius) : null;
    const [fx, fy] = toScreen(d.from[0], d.from[1]);
    if (tipSnap && Math.hypot(tipSnap.p[0] - d.from[0], tipSnap.p[1] - d.from[1]) > 0) {
      to = tipSnap.p;
      d.snapped = `to ${tipSnap.label}`;
    } else if (Math.hypot(p[0] - fx, p[1] - fy) > 6) {
      const ang = angleOf(to[0] - d.from[0], to[1] - d.from[1]);
      const c = snapDirection(ang);
      if (c) {
        const len = Math.hypot(to[0] - d.from[0], to[1] - d.from[1]);
        const u = dirOf(c.angle);
        to = [d.from[0] + len * u[0], d.from[1] + len * u[1]];
        d.snapped = c.text;
        d.snapAngle = c.angle;
      } else d.snapAngle = null;
    }
    d.to = to;
    describeDrag(d);
    drawCanvas();
  });

  function endPointer(ev, cancelled) {
    state.pointers.delete(ev.pointerId);
    if (state.pinch) {
      if (state.pointers.size < 2) state.pinch = null;
      return;
    }
    const d = state.drag;
    if (!d || d.id !== ev.pointerId) return;
    state.drag = null;
    if (cancelled) { drawCanvas(); return; }
    if (d.kind === "tap") {
      tap(d.at);
      return;
    }
    if ((d.kind === "vector" || d.kind === "line") && d.to) {
      const [fx, fy] = toScreen(d.from[0], d.from[1]);
      const [tx, ty] = toScreen(d.to[0], d.to[1]);
      if (Math.hypot(tx - fx, ty - fy) < 4) { drawCanvas(); return; }
      if (!d.name) { say("Choose which vector first.", false); drawCanvas(); return; }
      if (d.kind === "vector") {
        addStep({ op: "vector", phase: state.phase, name: d.name, tail: si(d.from), tip: si(d.to) });
      } else {
        const ang = d.snapAngle ?? angleOf(d.to[0] - d.from[0], d.to[1] - d.from[1]);
        addStep({ op: "line", phase: state.phase, name: d.name, through: si(d.from), angle: ang });
      }
      return;
    }
    drawCanvas();
  }
  canvas.addEventListener("pointerup", (ev) => endPointer(ev, false));
  canvas.addEventListener("pointercancel", (ev) => endPointer(ev, true));
  // zoom: Ctrl (or Cmd) and the wheel, or a pinch on a touchpad (the browser sends it as
  // a wheel event with ctrlKey); a plain wheel scrolls the notebook as usual
  canvas.addEventListener("wheel", (ev) => {
    if (!(ev.ctrlKey || ev.metaKey)) return;
    ev.preventDefault();
    const p = local(ev);
    zoomBy(Math.exp(-ev.deltaY * 0.01), p[0], p[1]);
  }, { passive: false });

  function tap(p) {
    if (state.tool === "point") {
      const lines = phaseSteps().filter(([st]) => st.op === "line").map(([st]) => st);
      let best = null;
      for (let a = 0; a < lines.length; a++) {
        for (let b = a + 1; b < lines.length; b++) {
          const x = crossing(disp(lines[a].through), dirOf(lines[a].angle),
            disp(lines[b].through), dirOf(lines[b].angle));
          if (!x) continue;
          const [sx, sy] = toScreen(x[0], x[1]);
          const dd = Math.hypot(sx - p[0], sy - p[1]);
          if (dd < 30 && (!best || dd < best.d)) best = { d: dd, x, names: [lines[a].name, lines[b].name] };
        }
      }
      if (!best) { say("Tap where two construction lines cross.", false); return; }
      addStep({ op: "point", phase: state.phase, lines: best.names, at: si(best.x) });
      return;
    }
    if (state.tool === "measure") {
      let best = null;
      for (const [st, i] of phaseSteps()) {
        if (st.op !== "vector") continue;
        const a = toScreen(...disp(st.tail));
        const b = toScreen(...disp(st.tip));
        const dd = segDist(p, a, b);
        if (dd < 16 && (!best || dd < best.d)) best = { d: dd, st, i };
      }
      if (!best) { readout.textContent = "Tap a vector to measure it."; return; }
      state.selected = best.i;
      const ph = phaseOf(state.phase);
      const v = disp(best.st.tip);
      const t = disp(best.st.tail);
      const len = Math.hypot(v[0] - t[0], v[1] - t[1]);
      readout.innerHTML = `${rich(best.st.name)}: ${fmt(len)} ${unitText(ph.unit)} ` +
        `(${fmt(len / ph.scale)} squares), at ${fmt(angleOf(v[0] - t[0], v[1] - t[1]))}\u00b0`;
      drawCanvas();
    }
  }

  function segDist(p, a, b) {
    const dx = b[0] - a[0];
    const dy = b[1] - a[1];
    const L = dx * dx + dy * dy || 1;
    const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L));
    return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
  }

  // ---------------------------------------------------------------- the linkage
  function drawLinkage() {
    const L = P.linkage;
    const pts = Object.values(L.points);
    const r = linkSvg.getBoundingClientRect();
    const W = Math.max(r.width, 50);
    const H = Math.max(r.height, 50);
    linkSvg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    linkSvg.replaceChildren();
    const xs = pts.map((p) => p[0]);
    const ys = pts.map((p) => p[1]);
    const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys)) || 1;
    const z = Math.min(W, H) / (span * 1.35);
    const cx = (Math.max(...xs) + Math.min(...xs)) / 2;
    const cy = (Math.max(...ys) + Math.min(...ys)) / 2;
    const T = (p) => [W / 2 + (p[0] - cx) * z, H / 2 - (p[1] - cy) * z];
    for (const [p, d] of L.slides) {
      const q = T(p);
      const seg = clipLine(q, [d[0], -d[1]], W, H);
      if (seg) s("line", { x1: seg[0], y1: seg[1], x2: seg[2], y2: seg[3], class: "apb-slide" }, linkSvg);
    }
    for (const link of L.links) {
      const q = link.map((n) => T(L.points[n]));
      s("polyline", { points: q.map((p) => p.join(",")).join(" "), class: "apb-link" }, linkSvg);
    }
    for (const [name, p] of Object.entries(L.points)) {
      const [x, y] = T(p);
      if (L.ground.includes(name)) {
        s("path", { d: `M${x - 9},${y + 11} L${x + 9},${y + 11}`, class: "apb-groundline" }, linkSvg);
      }
      s("circle", { cx: x, cy: y, r: 4.5, class: "apb-pin" }, linkSvg);
      const t = s("text", { x: x + 7, y: y - 7, class: "apb-small" }, linkSvg);
      t.innerHTML = rich(name).replace(/<sub>(\d)<\/sub>/g, '<tspan dy="3" font-size="75%">$1</tspan>');
    }
    // a length scale bar
    const bar = niceLen(span / 4);
    const [bx] = [10];
    s("line", { x1: bx, y1: H - 10, x2: bx + bar * z, y2: H - 10, class: "apb-bar" }, linkSvg);
    const bt = s("text", { x: bx, y: H - 15, class: "apb-small" }, linkSvg);
    bt.textContent = `${fmt(bar)} ${L.unit}`;
  }

  function niceLen(x) {
    const e = Math.floor(Math.log10(x));
    for (const m of [5, 2, 1]) if (m * 10 ** e <= x) return m * 10 ** e;
    return 10 ** e;
  }

  given.innerHTML = P.given.map(([k, v]) => `<span>${rich(k)} = ${rich(v)}</span>`).join(" ");

  // ---------------------------------------------------------------- tabs, tools, panels
  function buildTabs() {
    tabs.replaceChildren();
    for (const ph of P.phases) {
      const sm = (model.get("summary") || {})[ph.id] || {};
      const count = sm.total != null ? ` ${sm.right}/${sm.total}` : "";
      tabs.append(h("button", {
        type: "button", role: "tab", class: ph.id === state.phase ? "on" : "",
        "aria-selected": String(ph.id === state.phase), "data-testid": `tab-${ph.id}`,
        html: esc(ph.title) + (count ? `<span class="apb-count">${count}</span>` : ""),
        onclick: () => { state.phase = ph.id; state.selected = null; everything(); },
      }));
    }
  }

  const vectorName = h("select", { "data-testid": "vector-name", "aria-label": "Which vector" });
  const lineName = h("select", { "data-testid": "line-name", "aria-label": "Which term's line" });

  function fillNames() {
    const ph = phaseOf(state.phase);
    const keepV = vectorName.value;
    const keepL = lineName.value;
    vectorName.replaceChildren(...ph.vectors.map((v) => h("option", { value: v.name, text: v.name })));
    lineName.replaceChildren(...ph.lines.map((n) => h("option", { value: n, text: `line of ${n}` })));
    if (ph.vectors.some((v) => v.name === keepV)) vectorName.value = keepV;
    if (ph.lines.includes(keepL)) lineName.value = keepL;
  }

  const TOOLS = [
    ["vector", "Vector", "Lay a vector: drag from a point (the pole, a tip) to its tip, or type it below"],
    ["line", "Line", "Draw a construction line: drag from the point it passes through along its direction"],
    ["point", "Crossing", "Mark the point where two construction lines cross: tap it"],
    ["measure", "Measure", "Tap a vector to read its length and direction"],
    ["read", "Read off", "Type the unknowns read off the polygon"],
    ["pan", "Pan", "Drag to move the drawing"],
  ];

  function buildTools() {
    tools.replaceChildren();
    for (const [id, text, tip] of TOOLS) {
      tools.append(h("button", {
        type: "button", class: state.tool === id ? "on" : "", title: tip, "aria-pressed": String(state.tool === id),
        "data-testid": `tool-${id}`, text,
        onclick: () => { state.tool = id; state.selected = null; buildTools(); buildPanel(); drawCanvas(); },
      }));
    }
    tools.append(h("span", { class: "apb-sep" }));
    tools.append(h("button", { type: "button", "data-testid": "undo", text: "Undo", onclick: undo }));
    tools.append(h("button", {
      type: "button", "data-testid": "clear", class: state.clearArmed ? "armed" : "",
      text: state.clearArmed ? "Clear this polygon?" : "Clear", onclick: clearPhase,
    }));
    tools.append(h("button", {
      type: "button", "data-testid": "next", text: "Show the next step",
      title: P.mode === "practice" ? "Show the next step (drawn dotted)" : "Say what to do next",
      onclick: () => model.send({ type: "next", phase: state.phase }),
    }));
  }

  function pointSelect(testid) {
    const sel = h("select", { "data-testid": testid, "aria-label": "From which point" });
    const pts = snapPoints();
    sel.replaceChildren(...pts.map((q, k) => h("option", { value: String(k), text: q.label })));
    sel.value = String(pts.length - (pts.length > 1 ? 2 : 1));
    const last = [...phaseSteps()].reverse().find(([st]) => st.op === "vector");
    if (last) {
      const k = pts.findIndex((q) => q.label === `the tip of ${last[0].name}`);
      if (k >= 0) sel.value = String(k);
    } else sel.value = "0";
    sel._points = pts;
    return sel;
  }

  function directionInputs(withSense) {
    const mode = h("select", { "data-testid": "dir-mode", "aria-label": "Direction" }, [
      h("option", { value: "perp", text: "\u27c2 perpendicular to" }),
      h("option", { value: "par", text: "\u2225 parallel to" }),
      h("option", { value: "angle", text: "at the angle" }),
    ]);
    const link = h("select", { "data-testid": "dir-link", "aria-label": "Link" },
      P.directions.map((d) => h("option", { value: d.id, html: rich(d.label) })));
    const angle = h("input", { type: "number", step: "any", "data-testid": "dir-angle",
      "aria-label": "Angle in degrees", placeholder: "deg", class: "apb-num" });
    const sense = h("span", { class: "apb-sense" });
    const senseName = `sense-${Math.random().toString(36).slice(2)}`;
    function senses() {
      sense.replaceChildren();
      const d = P.directions.find((x) => x.id === link.value);
      const base = mode.value === "perp" ? d.angle + 90 : d.angle;
      [base, base + 180].forEach((a, k) => {
        const aa = ((a % 360) + 360) % 360;
        const id = `${senseName}-${k}`;
        const r = h("input", { type: "radio", name: senseName, id, value: String(aa), "data-testid": `sense-${k}` });
        const arrowDeg = -aa;
        sense.append(h("label", { for: id, class: "apb-sense-opt" }, [r,
          h("span", { class: "apb-arrow", style: `transform: rotate(${arrowDeg}deg)`, text: "\u2192" }),
          h("span", { text: ` ${fmt(aa)}\u00b0` })]));
      });
    }
    function sync() {
      const byAngle = mode.value === "angle";
      link.style.display = byAngle ? "none" : "";
      angle.style.display = byAngle ? "" : "none";
      if (withSense && !byAngle) senses(); else sense.replaceChildren();
    }
    mode.addEventListener("change", sync);
    link.addEventListener("change", sync);
    sync();
    const value = () => {
      if (mode.value === "angle") return parseFloat(angle.value);
      if (withSense) {
        const r = sense.querySelector("input:checked");
        return r ? parseFloat(r.value) : NaN;
      }
      const d = P.directions.find((x) => x.id === link.value);
      return mode.value === "perp" ? d.angle + 90 : d.angle;
    };
    return { nodes: [mode, link, angle, sense], value };
  }

  function row(labelText, nodes) {
    return h("div", { class: "apb-row" }, [h("span", { class: "apb-key", html: labelText }), ...nodes]);
  }

  function buildPanel() {
    const ph = phaseOf(state.phase);
    panel.replaceChildren();
    const tip = TOOLS.find((t) => t[0] === state.tool);
    if (tip) panel.append(h("div", { class: "apb-tip", text: tip[2] + "." }));
    if (state.tool === "vector") {
      const len = h("input", { type: "number", step: "any", min: "0", "data-testid": "length",
        "aria-label": "Length", class: "apb-num" });
      const lenUnit = h("select", { "data-testid": "length-unit", "aria-label": "Length unit" }, [
        h("option", { value: "unit", text: unitPlain(ph.unit) }),
        h("option", { value: "squares", text: "squares" }),
      ]);
      const dir = directionInputs(true);
      const from = pointSelect("from");
      panel.append(
        row("vector", [vectorName]),
        row("length", [len, lenUnit]),
        row("direction", dir.nodes),
        row("from", [from]),
        h("button", { type: "button", class: "apb-go", "data-testid": "place", text: "Place the vector",
          onclick: () => {
            let L = parseFloat(len.value);
            const a = dir.value();
            if (!(L > 0) || !isFinite(a)) { say("Type a length above 0 and choose a direction and its sense.", false); return; }
            if (lenUnit.value === "squares") L *= ph.scale;
            const p0 = from._points[parseInt(from.value, 10)].p;
            const u = dirOf(a);
            addStep({ op: "vector", phase: state.phase, name: vectorName.value, tail: si(p0),
              tip: si([p0[0] + L * u[0], p0[1] + L * u[1]]) });
          } }),
      );
    } else if (state.tool === "line") {
      const dir = directionInputs(false);
      const from = pointSelect("through");
      panel.append(
        row("line of", [lineName]),
        row("direction", dir.nodes),
        row("through", [from]),
        h("button", { type: "button", class: "apb-go", "data-testid": "draw-line", text: "Draw the line",
          onclick: () => {
            const a = dir.value();
            if (!isFinite(a)) { say("Choose a direction.", false); return; }
            const p0 = from._points[parseInt(from.value, 10)].p;
            addStep({ op: "line", phase: state.phase, name: lineName.value, through: si(p0), angle: a });
          } }),
      );
    } else if (state.tool === "point") {
      const lines = phaseSteps().filter(([st]) => st.op === "line").map(([st]) => st.name);
      const a = h("select", { "data-testid": "cross-a" }, lines.map((n) => h("option", { value: n, text: n })));
      const b = h("select", { "data-testid": "cross-b" }, lines.map((n) => h("option", { value: n, text: n })));
      if (lines.length > 1) b.value = lines[1];
      panel.append(
        row("lines of", [a, h("span", { text: " and " }), b]),
        h("button", { type: "button", class: "apb-go", "data-testid": "mark", text: "Mark where they cross",
          onclick: () => {
            const la = phaseSteps().find(([st]) => st.op === "line" && st.name === a.value);
            const lb = phaseSteps().find(([st]) => st.op === "line" && st.name === b.value);
            if (!la || !lb || a.value === b.value) { say("Choose two different lines.", false); return; }
            const x = crossing(disp(la[0].through), dirOf(la[0].angle), disp(lb[0].through), dirOf(lb[0].angle));
            if (!x) { say("These lines are parallel: they do not cross.", false); return; }
            addStep({ op: "point", phase: state.phase, lines: [a.value, b.value], at: si(x) });
          } }),
      );
    } else if (state.tool === "read") {
      for (const r of ph.reads) {
        const input = h("input", { type: "number", step: "any", "data-testid": `read-${r.name}`,
          "aria-label": r.label, class: "apb-num" });
        const done = phaseSteps().find(([st]) => st.op === "read" && st.name === r.name);
        if (done) input.value = fmt(done[0].value * r.factor);
        panel.append(row(rich(r.label), [input, h("span", { html: " " + unitText(r.unit) }),
          h("button", { type: "button", "data-testid": `enter-${r.name}`, text: "Enter",
            onclick: () => {
              const x = parseFloat(input.value);
              if (!isFinite(x)) { say("Type a number.", false); return; }
              addStep({ op: "read", phase: state.phase, name: r.name, value: x / r.factor });
            } })]));
      }
      panel.append(h("div", { class: "apb-tip", html:
        "Angular rates are counter-clockwise positive; measure a vector with the Measure tool." }));
    }
  }

  // ---------------------------------------------------------------- feedback
  function say(text, ok) {
    state.message = { text, ok };
    showMessage();
  }

  function showMessage() {
    const m = state.message;
    message.className = "apb-message" + (m ? (m.ok === true ? " ok" : m.ok === false ? " bad" : " info") : "");
    message.innerHTML = m ? rich(m.text) : "";
  }

  function buildList() {
    const verdicts = verdictsNow();
    list.replaceChildren();
    let n = 0;
    for (const [st, i] of phaseSteps()) {
      n += 1;
      const v = verdicts[i] || {};
      const mark = v.ok === true ? "\u2713" : v.ok === false ? "\u2717" : "\u2022";
      const what = st.op === "point" ? "crossing" : st.op === "line" ? `line of ${st.name}`
        : st.op === "read" ? `${st.name} = ${fmt(st.value)}` : st.name;
      const li = h("li", { class: v.ok === true ? "ok" : v.ok === false ? "bad" : "", "data-step": String(i) }, [
        h("span", { class: "apb-mark", text: mark }),
        h("span", { class: "apb-what", html: `${n}. ${rich(what)}` }),
        h("span", { class: "apb-why", html: v.message ? rich(v.message) : "" }),
        h("button", { type: "button", class: "apb-del", "aria-label": "Remove this step", text: "\u00d7",
          onclick: () => removeStep(i) }),
      ]);
      list.append(li);
    }
    const sm = (model.get("summary") || {})[state.phase] || {};
    summary.textContent = sm.total != null
      ? `${sm.right} of ${sm.total} steps of this polygon right`
      : `${sm.drawn || 0} steps drawn on this polygon`;
  }

  function everything() {
    fillNames();
    buildTabs();
    buildTools();
    buildPanel();
    buildList();
    drawCanvas();
    showMessage();
  }

  // ---------------------------------------------------------------- model events
  let lastCount = steps().length;
  const onSteps = () => {
    readout.textContent = "";
    buildPanel();
    buildList();
    drawCanvas();
  };
  // `judged` counts Python's judgements: each one ends the wait for the steps on screen
  const onJudged = () => {
    state.pending = false;
    const verdicts = model.get("verdicts") || [];
    const all = steps();
    if (all.length && all.length >= lastCount && verdicts.length === all.length) {
      const v = verdicts[all.length - 1];
      if (v && all[all.length - 1].phase === state.phase) say(v.message, v.ok);
    }
    lastCount = all.length;
    buildList();
    buildTabs();
    drawCanvas();
  };
  const onHint = () => {
    const hint = model.get("hint") || {};
    state.ghost = hint;
    if (hint.phase && hint.phase !== state.phase) { state.phase = hint.phase; everything(); }
    say(hint.text || "", null);
    if (hint.ghost) fit(false);
    drawCanvas();
  };
  const onStatus = () => { const t = model.get("status"); if (t) say(t, false); };
  model.on("change:steps", onSteps);
  model.on("change:judged", onJudged);
  model.on("change:summary", buildTabs);
  model.on("change:hint", onHint);
  model.on("change:status", onStatus);

  const resize = new ResizeObserver(() => {
    const w = root.getBoundingClientRect().width;
    root.classList.toggle("narrow", w < 640);
    drawLinkage();
    drawCanvas();
  });
  resize.observe(root);
  requestAnimationFrame(() => { everything(); drawLinkage(); if (steps().length) fit(true); });

  return () => {
    resize.disconnect();
    model.off("change:steps", onSteps);
    model.off("change:judged", onJudged);
    model.off("change:summary", buildTabs);
    model.off("change:hint", onHint);
    model.off("change:status", onStatus);
  };
}

export default { render };
