// Browser test of the map viewer; started by tests/viewer/run.sh (which
// checks that node, Chromium and playwright-core are there).
//
// Every expectation comes from outside the page: the polygon seen in a
// direction from `genbsp locate` (the exact point location of the library),
// adjacency from the map's JSON, "away from every edge" from the arcs of the
// map's JSON measured here (one thing is the page's: which face of a polygon
// a pixel is in, for the highlight; its polygon is checked against genbsp
// locate).  What is read from the page: its state (document.body.dataset,
// window.genbspView), the pixels of its canvas, its screenshots, its SVG.
import { execFileSync, spawnSync } from "node:child_process";
import { mkdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";

// ------------------------------------------------------------ arguments
const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, "")] = process.argv[i + 1];
const genbsp = resolve(args.genbsp), workdir = resolve(args.workdir), web = resolve(args.web);
const work = join(workdir, "viewer-test");
const SHOTS = process.env.GENBSP_VIEWER_SCREENSHOTS ? resolve(process.env.GENBSP_VIEWER_SCREENSHOTS) : null;
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });

const req = createRequire(join(workdir, "x.js"));
const { chromium } = req("playwright-core");

const started = Date.now();

// --------------------------------------------------------------- checks
let passed = 0, failed = 0, skipped = 0;
function check(name, ok, detail = "") {
  if (ok) passed++; else failed++;
  console.log(`${ok ? "PASS" : "FAIL"} ${name}${detail ? ": " + detail : ""}`);
  return ok;
}
function skip(name, why) {
  skipped++;
  console.log(`SKIP ${name}: ${why}`);
}
function info(line) { console.log(`     ${line}`); }
// A step that throws (a timeout, a crash) ends the run as one more failure.
let browser = null;
for (const event of ["uncaughtException", "unhandledRejection"]) {
  process.on(event, async (e) => {
    check("the test ran to its end", false, String((e && e.stack) || e).split("\n").slice(0, 4).join(" | "));
    console.log(`${passed} passed, ${failed} failed`);
    try { if (browser) await browser.close(); } catch {}
    process.exit(1);
  });
}

// ------------------------------------------------------------- genbsp
const run = (argv) => execFileSync(genbsp, argv, { encoding: "utf8", maxBuffer: 1 << 30 });
// `genbsp view` exists when its own help comes back (CLI11 answers an unknown
// subcommand's --help with the program's help, also with status 0).
const viewHelp = spawnSync(genbsp, ["view", "--help"], { encoding: "utf8" });
const hasView = viewHelp.status === 0 && /Usage:\S*\s+\S*genbsp view\b/.test(viewHelp.stdout);
// GENBSP_VIEWER_EMBED=1: make the pages from web/viewer.html as it is on disk
// (genbsp map + web/embed.mjs), even where `genbsp view` exists: `genbsp view`
// writes the copy of web/viewer.html compiled into it.
const useView = hasView && !/^(1|true|yes)$/i.test(process.env.GENBSP_VIEWER_EMBED || "");

/** A scene of `family` with `n`: its OFF file, eye, MAP.json (parsed) and the viewer page. */
function makeScene(family, n) {
  const off = join(work, `${family}${n}.off`), mapPath = join(work, `${family}${n}.json`), html = join(work, `${family}${n}.html`);
  const eye = run(["scene", family, "--n", String(n), "-o", off]).trim();
  run(["map", off, "--eye", eye, "-o", mapPath]);
  if (useView) run(["view", off, "--eye", eye, "-o", html]);
  else execFileSync("node", [join(web, "embed.mjs"), mapPath, "-o", html]);
  const map = JSON.parse(readFileSync(mapPath, "utf8"));
  return { family, n, off, eye, map, html, geo: geometry(map) };
}

/** A viewer page with its two lines of data put back to the placeholders, and the data. */
function unembed(text) {
  const m = /^const MAP = (.*);$/m.exec(text), c = /^const COLORS = (.*);$/m.exec(text);
  if (!m || !c) return null;
  return { template: text.replace(m[0], "const MAP = /*GENBSP_MAP*/null;").replace(c[0], "const COLORS = /*GENBSP_COLORS*/null;"),
    map: JSON.parse(m[1]), colors: JSON.parse(c[1]) };
}

/** Polygons seen in directions (arrays [x, y, z]), by `genbsp locate`, in one run. */
function locateAll(scene, dirs) {
  if (dirs.length === 0) return [];
  const file = join(work, "dirs.txt");
  // Decimals without exponents: genbsp reads them exactly.
  writeFileSync(file, dirs.map((d) => d.map((v) => v.toFixed(20)).join(" ")).join("\n") + "\n");
  const out = run(["locate", scene.off, "--eye", scene.eye, "--dirs", file]).trim().split(/\s+/).map(Number);
  if (out.length !== dirs.length) throw new Error(`genbsp locate printed ${out.length} answers for ${dirs.length} directions`);
  return out;
}

// ---------------------------------------------- the map's own geometry
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const unit = (a) => { const l = norm(a); return [a[0] / l, a[1] / l, a[2] / l]; };
const angle = (a, b) => Math.atan2(norm(cross(a, b)), dot(a, b));

/** Arcs (each edge once) and adjacency of a map. */
function geometry(map) {
  const V = map.vertices.map(unit), faceOf = new Map(), arcs = [];
  map.faces.forEach((f, fi) => f.cycles.forEach((c) => c.forEach((a, i) => faceOf.set(`${a},${c[(i + 1) % c.length]}`, fi))));
  for (const k of faceOf.keys()) {
    const [a, b] = k.split(",").map(Number);
    if (a < b || !faceOf.has(`${b},${a}`)) {
      const n = cross(V[a], V[b]), l = norm(n);
      arcs.push({ a: V[a], b: V[b], n: l > 0 ? [n[0] / l, n[1] / l, n[2] / l] : null });
    }
  }
  /** The polygons of the faces sharing an edge with polygon p's faces ("-1" included), sorted. */
  function neighbours(p) {
    const mine = new Set(map.faces.map((f, i) => (f.polygon === p ? i : -1)).filter((i) => i >= 0));
    const out = new Set();
    for (const fi of mine) for (const c of map.faces[fi].cycles) c.forEach((a, i) => {
      const t = faceOf.get(`${c[(i + 1) % c.length]},${a}`);
      if (t !== undefined && !mine.has(t)) out.add(map.faces[t].polygon);
    });
    return [...out].sort((x, y) => x - y);
  }
  /** The faces of polygon p, and the other faces sharing an edge with them. */
  function highlight(p) {
    const mine = new Set(map.faces.map((f, i) => (f.polygon === p ? i : -1)).filter((i) => i >= 0)), next = new Set();
    for (const fi of mine) for (const c of map.faces[fi].cycles) c.forEach((a, i) => {
      const t = faceOf.get(`${c[(i + 1) % c.length]},${a}`);
      if (t !== undefined && !mine.has(t)) next.add(t);
    });
    return { faces: mine, neighbourFaces: next };
  }
  /** The angle from unit vector p to the nearest edge of the map. */
  function edgeDistance(p) {
    let best = Infinity;
    for (const e of arcs) {
      let d;
      if (e.n) {
        const pn = dot(p, e.n), q = [p[0] - pn * e.n[0], p[1] - pn * e.n[1], p[2] - pn * e.n[2]];
        if (norm(q) > 0 && dot(cross(e.a, q), e.n) >= 0 && dot(cross(q, e.b), e.n) >= 0) d = Math.atan2(Math.abs(pn), norm(q));
      }
      if (d === undefined) d = Math.min(angle(p, e.a), angle(p, e.b));
      if (d < best) best = d;
    }
    return best;
  }
  return { arcs, neighbours, highlight, edgeDistance };
}

// -------------------------------------------------------------- browser
const consoleErrors = [], blocked = [];
browser = await chromium.launch({ executablePath: args.chromium, headless: true, args: ["--no-sandbox"] });
info(`Chromium ${browser.version()}, playwright-core ${req("playwright-core/package.json").version}, ` +
  `HTML from ${useView ? "genbsp view" : "genbsp map + web/embed.mjs"}`);
const context = await browser.newContext({ viewport: { width: 1100, height: 760 }, offline: true, acceptDownloads: true });
await context.route("**/*", (route) => {
  const url = route.request().url();
  if (url.startsWith("file:") || url.startsWith("data:") || url.startsWith("blob:")) return route.continue();
  blocked.push(url);
  return route.abort();
});

async function open(scene, hash = "") {
  const page = await context.newPage();
  page.on("console", (m) => { if (m.type() === "error") consoleErrors.push(`${scene.family}: ${m.text()}`); });
  page.on("pageerror", (e) => consoleErrors.push(`${scene.family}: ${e.message}`));
  await page.goto(pathToFileURL(scene.html).href + hash);
  await page.waitForFunction(() => document.body.dataset.ready === "true", null, { timeout: 60000 });
  return page;
}
const ds = (page) => page.evaluate(() => Object.assign({}, document.body.dataset));
const settled = (page) => page.evaluate(() => window.genbspView.settled());
const fmt = (v) => `[${v.map((x) => x.toFixed(5)).join(", ")}]`;

async function drag(page, x0, y0, dx, dy) {
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + dx, y0 + dy, { steps: 12 });
  await page.mouse.up();
  await settled(page);
}

/**
 * The canvas's pixels on a grid, with each pixel's direction and the
 * directions 2.5 pixels around it (to tell pixels well inside one face).
 */
function sampleGrid(page, cols, rows) {
  return page.evaluate(([cols, rows]) => {
    const v = window.genbspView, out = [], W = innerWidth, H = innerHeight;
    for (let j = 0; j < rows; j++) for (let i = 0; i < cols; i++) {
      const x = Math.floor(((i + 0.5) * W) / cols) + 0.5, y = Math.floor(((j + 0.5) * H) / rows) + 0.5;
      const d = v.directionAt(x, y);
      if (!d) continue;
      const ring = [];
      for (let k = 0; k < 8; k++) ring.push(v.directionAt(x + 2.5 * Math.cos((k * Math.PI) / 4), y + 2.5 * Math.sin((k * Math.PI) / 4)));
      out.push({ x, y, d, ring, rgb: v.pixel(x, y) });
    }
    return out;
  }, [cols, rows]);
}
/** The samples whose 2.5-pixel neighbourhood is inside one face of the map (measured on the map's arcs). */
function interior(scene, samples) {
  return samples.filter((s) => {
    if (s.ring.some((r) => !r)) return false;
    const reach = Math.max(...s.ring.map((r) => angle(s.d, r)));
    return scene.geo.edgeDistance(s.d) > reach;
  });
}
const rgbHex = (c) => "#" + c.slice(0, 3).map((v) => v.toString(16).padStart(2, "0")).join("");
const closeRGB = (c, hex) => [1, 3, 5].every((k, i) => Math.abs(c[i] - parseInt(hex.slice(k, k + 2), 16)) <= 2);

/** Views in which the drawing is compared with genbsp locate, pixel by pixel. */
const VIEWS = [
  { name: "perspective", projection: "perspective" },
  { name: "perspective 30 deg, elsewhere", projection: "perspective", fov: 30, dir: [0.3, -0.5, 0.8] },
  { name: "stereographic 60 deg (frustum)", projection: "stereographic", fov: 60, dir: [-0.6, 0.2, 0.5] },
  { name: "stereographic 300 deg (wide)", projection: "stereographic", fov: 300 },
  { name: "fisheye 120 deg", projection: "fisheye", fov: 120, dir: [0.2, 0.9, -0.1] },
  { name: "fisheye 360 deg", projection: "fisheye", fov: 360, dir: [-0.7, 0.1, 0.3] },
  { name: "panorama 360 deg", projection: "equirectangular", fov: 360 },
  { name: "panorama looking up", projection: "equirectangular", fov: 360, dir: [0.05, 0.02, 1] },
  { name: "panorama 140 deg", projection: "equirectangular", fov: 140, dir: [0.4, -0.8, -0.3] },
  { name: "globe", mode: "globe" },
];

/** With one colour per polygon (index + 1 as #rrggbb, background black), each interior pixel names its polygon. */
async function pixelChecks(scene, page, views, cols, rows) {
  const ncol = Math.max(0, ...scene.map.faces.map((f) => f.polygon)) + 1;
  const ids = Array.from({ length: ncol }, (_, p) => "#" + (p + 1).toString(16).padStart(6, "0"));
  await page.evaluate((ids) => window.genbspView.setOptions({ edges: false, overlay: false, colours: ids, background: "#000000" }), ids);
  await page.evaluate(() => window.genbspView.select(null));
  const home = await page.evaluate(() => window.genbspView.viewDirection());
  const all = [];
  for (const v of views) {
    await page.evaluate(async (v) => {
      const g = window.genbspView;
      await g.setMode("observer");
      if (v.projection) await g.setProjection(v.projection);
      if (v.fov) await g.setFov(v.fov);
      if (v.dir) await g.setView(v.dir);
      if (v.mode === "globe") await g.setMode("globe");
    }, { ...v, dir: v.dir || home });
    const s = interior(scene, await sampleGrid(page, cols, rows));
    all.push({ view: v, samples: s });
  }
  const expected = locateAll(scene, all.flatMap((a) => a.samples.map((s) => s.d)));
  let k = 0;
  for (const { view, samples } of all) {
    const bad = [];
    for (const s of samples) {
      const want = expected[k++], got = ((s.rgb[0] << 16) | (s.rgb[1] << 8) | s.rgb[2]) - 1;
      if (got !== want) bad.push(`(${s.x},${s.y}) shows ${got}, genbsp locate says ${want}`);
    }
    const enough = samples.length >= 10;
    check(`${scene.family}: ${view.name}: pixels show the polygon genbsp locate finds`, enough && bad.length === 0,
      `${samples.length - bad.length}/${samples.length} pixels well inside a face` + (bad.length ? "; " + bad.slice(0, 3).join("; ") : "") +
        (enough ? "" : " (fewer than 10 such pixels)"));
  }
  await page.evaluate(async (home) => {
    const g = window.genbspView;
    await g.setOptions({ edges: true, overlay: true, colours: null, background: null });
    await g.setMode("observer"); await g.setProjection("perspective"); await g.setView(home);
  }, home);
}

// ================================================================ tests
const small = makeScene("bricks", 12);
info(`small scene: bricks --n 12, eye ${small.eye}, ${small.map.faces.length} faces`);
let page = await open(small);
const first = await page.evaluate(() => ({ dir: window.genbspView.viewDirection(), fov: window.genbspView.fov() }));

// Loading.
{
  const m = await page.evaluate(() => window.genbspView.map);
  check("bricks: the page shows the embedded map", m && m.faces === small.map.faces.length && m.vertices === small.map.vertices.length,
    JSON.stringify(m));
  const d = await ds(page);
  check("bricks: the state is exposed on document.body.dataset",
    ["centerPolygon", "selectedPolygon", "neighbours", "projection", "frameMs", "fov"].every((k) => k in d) && d.projection === "perspective",
    JSON.stringify(d));
  check("bricks: no console errors on load", consoleErrors.length === 0, consoleErrors.slice(0, 3).join(" | "));
  // One self-contained file: it names nothing to load and loads nothing.
  const html = readFileSync(small.html, "utf8");
  const refs = html.match(/<(link|img|iframe|object|embed|source)\b|\b(src|href)\s*=\s*["']?(https?:)?\/\/|url\(\s*["']?(https?:)?\/\/|@import|\bimport\s*\(|\bfetch\s*\(|XMLHttpRequest|WebSocket|EventSource|sendBeacon/gi) || [];
  check("bricks: the page names no resource to load", refs.length === 0, refs.slice(0, 3).join(" "));
  const loaded = await page.evaluate(() => performance.getEntriesByType("resource").map((e) => e.name));
  check("bricks: the page loaded nothing but itself", loaded.length === 0 && blocked.length === 0, [...loaded, ...blocked].slice(0, 3).join(" "));
}

// Drags: the picture follows the pointer (a drag to the right turns the view
// to the left, a drag down turns it up), and the polygon at the centre is the
// one genbsp locate finds in the view direction.  Each drag starts from its
// own view, well away from the zenith and the nadir (where turning left and
// right barely moves the view direction).
{
  const W = 1100, H = 760;
  const drags = [
    { from: [0.5, -0.3, 0.8], move: [160, 40] }, { from: [-0.4, 0.6, 0.7], move: [-90, 120] },
    { from: [0.9, 0.2, 0.4], move: [220, -70] }, { from: [0.1, -0.8, 0.6], move: [-300, -20] },
    { from: [-0.7, -0.5, 0.5], move: [60, 200] }, { from: [0.6, 0.6, 0.5], move: [-140, -160] },
    { from: [0.2, 0.3, 0.9], move: [90, 30] }, { from: [-0.9, 0.1, 0.4], move: [-40, 90] },
  ];
  const projections = ["perspective", "stereographic", "fisheye", "equirectangular"];
  const records = [];
  for (let i = 0; i < drags.length; i++) {
    await page.evaluate(([p, d]) => { window.genbspView.setProjection(p); return window.genbspView.setView(d); }, [projections[i % 4], drags[i].from]);
    const before = await page.evaluate(() => window.genbspView.viewDirection());
    await drag(page, W / 2 - 50, H / 2 + 40, drags[i].move[0], drags[i].move[1]);
    const after = await page.evaluate(() => window.genbspView.viewDirection());
    const d = await ds(page);
    records.push({ i, projection: projections[i % 4], move: drags[i].move, before, after, centre: Number(d.centerPolygon) });
  }
  // Screen right of the view before the drag (the world's up is +z).
  const follows = records.filter((r) => {
    const right = unit(cross(r.before, [0, 0, 1])), dv = [0, 1, 2].map((k) => r.after[k] - r.before[k]);
    return angle(r.before, r.after) > 1e-3 && Math.sign(dot(dv, right)) === -Math.sign(r.move[0]) && Math.sign(dv[2]) === Math.sign(r.move[1]);
  });
  check("bricks: mouse drags turn the view, the picture following the pointer", follows.length === records.length,
    `${follows.length}/${records.length} drags` + (follows.length < records.length
      ? "; " + records.filter((r) => !follows.includes(r)).map((r) => `drag ${r.i + 1} ${fmt(r.before)} -> ${fmt(r.after)}`).join("; ") : ""));
  // In the panorama a drag moves every point of the picture by the pointer's motion, exactly.
  {
    await page.evaluate(() => { window.genbspView.setProjection("equirectangular"); return window.genbspView.setView([0.3, 0.8, 0.2]); });
    const [x0, y0, dx, dy] = [430, 330, 137, 61];
    const d0 = await page.evaluate(([x, y]) => window.genbspView.directionAt(x, y), [x0, y0]);
    await drag(page, x0, y0, dx, dy);
    const q = await page.evaluate((d) => window.genbspView.pixelAt(d), d0);
    check("bricks: panorama: the point under the pointer stays under it", Math.hypot(q[0] - x0 - dx, q[1] - y0 - dy) < 0.5,
      `dragged (${x0}, ${y0}) -> (${x0 + dx}, ${y0 + dy}); that direction is now at (${q[0].toFixed(2)}, ${q[1].toFixed(2)})`);
  }
  const expected = locateAll(small, records.map((r) => r.after));
  let compared = 0;
  records.forEach((r, k) => {
    if (small.geo.edgeDistance(r.after) < 1e-9) { skip(`bricks: drag ${r.i + 1}`, "the view direction is on an edge of the map"); return; }
    compared++;
    check(`bricks: drag ${r.i + 1} (${r.projection}): the centre polygon is genbsp locate's`, r.centre === expected[k],
      `page ${r.centre}, genbsp locate ${expected[k]}, direction ${fmt(r.after)}`);
  });
  check("bricks: drags compared with genbsp locate", compared >= 4 && new Set(expected).size >= 3,
    `${compared} compared, ${new Set(expected).size} different polygons`);
}

// Wheel: the field of view.
{
  await page.evaluate(() => window.genbspView.setProjection("perspective"));
  const f0 = Number((await ds(page)).fov);
  await page.mouse.move(550, 380);
  await page.mouse.wheel(0, -400);
  await page.waitForFunction((f0) => Number(document.body.dataset.fov) < f0, f0, { timeout: 60000 }).catch(() => {});
  const f1 = Number((await ds(page)).fov);
  check("bricks: the wheel narrows the field of view", f1 < f0, `${f0} -> ${f1}`);
  await page.mouse.wheel(0, 400);
  await page.waitForFunction((f1) => Number(document.body.dataset.fov) > f1, f1, { timeout: 60000 }).catch(() => {});
  check("bricks: and widens it back", Number((await ds(page)).fov) > f1);
  // Touch: two fingers moving apart narrow the field of view in proportion, one finger turns the view.
  const cdp = await context.newCDPSession(page);
  const touch = (type, pts) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: pts.map(([x, y], id) => ({ x, y, id })) });
  await page.evaluate(() => window.genbspView.setFov(90));
  await touch("touchStart", [[450, 380], [650, 380]]);
  for (let k = 1; k <= 10; k++) await touch("touchMove", [[450 - 10 * k, 380], [650 + 10 * k, 380]]);
  await touch("touchEnd", []);
  await settled(page);
  const f2 = Number((await ds(page)).fov);
  check("bricks: a pinch (fingers 200 -> 400 px apart) halves the field of view", Math.abs(f2 - 45) < 0.5, `90 -> ${f2}`);
  const t0 = await page.evaluate(() => window.genbspView.viewDirection());
  await touch("touchStart", [[500, 400]]);
  for (let k = 1; k <= 10; k++) await touch("touchMove", [[500 + 12 * k, 400]]);
  await touch("touchEnd", []);
  await settled(page);
  const t1 = await page.evaluate(() => window.genbspView.viewDirection());
  check("bricks: a one-finger drag turns the view", angle(t0, t1) > 1e-2, `${fmt(t0)} -> ${fmt(t1)}`);
  await cdp.detach();
}

// Clicks: the polygon genbsp locate finds is selected, its neighbours are the map's.
{
  await page.evaluate(() => window.genbspView.setView([0.2, -0.4, 0.9], 100));
  const grid = interior(small, await sampleGrid(page, 9, 7)).filter((s) => s.y > 60 && s.y < 600);
  const pick = [];
  for (const s of grid) if (pick.length < 4 && pick.every((q) => Math.hypot(q.x - s.x, q.y - s.y) > 150)) pick.push(s);
  const want = locateAll(small, pick.map((s) => s.d));
  check("bricks: click targets found", pick.length >= 3, `${pick.length} pixels well inside faces`);
  for (let k = 0; k < pick.length; k++) {
    const s = pick[k];
    await page.mouse.click(s.x, s.y);
    await settled(page);
    const d = await ds(page);
    const dir = await page.evaluate(([x, y]) => window.genbspView.directionAt(x, y), [s.x, s.y]);
    const [p] = locateAll(small, [dir]);
    check(`bricks: click ${k + 1} at (${s.x}, ${s.y}) selects genbsp locate's polygon`, d.selectedPolygon === String(p) && p === want[k],
      `page ${d.selectedPolygon}, genbsp locate ${p}`);
    const nb = small.geo.neighbours(p).join(",");
    check(`bricks: click ${k + 1}: the neighbours are the map's`, d.neighbours === nb && nb.length > 0, `page "${d.neighbours}", map "${nb}"`);
    const text = await page.evaluate(() => document.getElementById("info").textContent);
    const shown = /selected: polygon (background \()?(-?\d+)/.exec(text);
    check(`bricks: click ${k + 1}: the page shows the polygon's index`, shown !== null && Number(shown[2]) === p, shown ? shown[0] : text);
  }
  // The highlight as drawn: every pixel well inside a face has the colour of
  // its face: the selected polygon's faces in one colour, the faces sharing
  // an edge with them in another (adjacency from the map's JSON), the others
  // their polygon's.  The face under a pixel is the page's; its polygon must
  // be genbsp locate's.
  const last = pick[pick.length - 1];
  if (last) {
    const d = await ds(page);
    const sel = Number(d.selectedPolygon), hl = small.geo.highlight(sel);
    const C = await page.evaluate(() => window.genbspView.colours);
    const samples = interior(small, await sampleGrid(page, 30, 20));
    const polys = locateAll(small, samples.map((s) => s.d));
    const faces = await page.evaluate((ds) => ds.map((d) => window.genbspView.locate(d).face), samples.map((s) => s.d));
    const colourOf = await page.evaluate((ps) => ps.map((p) => window.genbspView.colourOf(p)), [...new Set(polys)]);
    const plain = new Map([...new Set(polys)].map((p, i) => [p, colourOf[i]]));
    let nSel = 0, nNb = 0;
    const bad = [];
    samples.forEach((s, i) => {
      const p = polys[i], f = faces[i];
      if (!(f >= 0 && f < small.map.faces.length) || small.map.faces[f].polygon !== p) {
        bad.push(`(${s.x},${s.y}) the page's face ${f} is not of polygon ${p}`);
        return;
      }
      const wantColour = hl.faces.has(f) ? (p < 0 ? C.selectedBackground : C.selected)
        : hl.neighbourFaces.has(f) ? (p < 0 ? C.neighbourBackground : C.neighbour) : plain.get(p);
      if (hl.faces.has(f)) nSel++; else if (hl.neighbourFaces.has(f)) nNb++;
      if (!closeRGB(s.rgb, wantColour)) bad.push(`(${s.x},${s.y}) face ${f} of polygon ${p}: ${rgbHex(s.rgb)} not ${wantColour}`);
    });
    check("bricks: the selected polygon and the faces next to it are drawn in their colours", bad.length === 0 && nSel > 0 && nNb > 0,
      `${samples.length} pixels, ${nSel} selected, ${nNb} in neighbouring faces` + (bad.length ? "; " + bad.slice(0, 3).join("; ") : ""));
  }
  await page.keyboard.press("Escape");
  await settled(page);
  check("bricks: Escape clears the selection", (await ds(page)).selectedPolygon === "");
}

// Keys 1-4 and the buttons switch projections; each draws differently, the centre polygon stays.
{
  const names = ["perspective", "stereographic", "fisheye", "equirectangular"];
  let ok = true;
  for (let k = 0; k < 4; k++) {
    await page.keyboard.press(String(k + 1));
    await settled(page);
    if ((await ds(page)).projection !== names[k]) ok = false;
  }
  check("bricks: keys 1-4 switch the projection", ok);
  await page.evaluate(() => window.genbspView.setProjection("perspective"));
  const centre0 = (await ds(page)).centerPolygon;
  const shots = [];
  for (const b of [...names, "globe"]) {
    await page.click(`#btn-${b}`);
    await settled(page);
    const d = await ds(page);
    shots.push({ b, png: await page.screenshot(), d });
    if (b !== "globe") {
      check(`bricks: button ${b} selects it`, d.projection === b && d.mode === "observer", `${d.mode} ${d.projection}`);
      check(`bricks: ${b}: the centre polygon stays ${centre0}`, d.centerPolygon === centre0, `got ${d.centerPolygon}`);
    } else check("bricks: button globe shows the globe", d.mode === "globe");
  }
  let distinct = true;
  for (let i = 0; i < shots.length; i++) for (let j = i + 1; j < shots.length; j++) if (shots[i].png.equals(shots[j].png)) distinct = false;
  check("bricks: every projection draws a different picture", distinct);
  // The globe turns with a drag and reports its own centre.
  const g0 = await page.evaluate(() => window.genbspView.globeDirection());
  await drag(page, 500, 420, 120, -60);
  const g1 = await page.evaluate(() => window.genbspView.globeDirection());
  const d = await ds(page);
  check("bricks: dragging turns the globe", angle(g0, g1) > 1e-3, `${fmt(g0)} -> ${fmt(g1)}`);
  if (small.geo.edgeDistance(g1) > 1e-9) {
    const [p] = locateAll(small, [g1]);
    check("bricks: globe: the centre polygon is genbsp locate's", d.centerPolygon === String(p), `page ${d.centerPolygon}, genbsp locate ${p}`);
  } else skip("bricks: globe centre", "on an edge of the map");
  await page.click("#btn-globe");
  await settled(page);
  check("bricks: the globe button goes back to the observer", (await ds(page)).mode === "observer");
}

// The other keys: G globe, E edges, R reset, arrows turn, + and - the field of view, H help.
{
  const view = () => page.evaluate(() => window.genbspView.viewDirection());
  const press = async (key) => { await page.keyboard.press(key); await settled(page); return ds(page); };
  await page.evaluate(() => window.genbspView.setProjection("perspective"));
  check("bricks: key G shows the globe and back", (await press("g")).mode === "globe" && (await press("g")).mode === "observer");
  const edgesOn = () => page.evaluate(() => document.getElementById("btn-edges").classList.contains("on"));
  const e0 = await edgesOn(), png0 = await page.screenshot();
  await press("e");
  const e1 = await edgesOn(), png1 = await page.screenshot();
  await press("e");
  check("bricks: key E toggles the edges", e0 && !e1 && (await edgesOn()) && !png0.equals(png1));
  const v0 = await view();
  await press("ArrowLeft");
  const v1 = await view();
  await press("ArrowUp");
  const v2 = await view(), right = unit(cross(v0, [0, 0, 1]));
  check("bricks: arrow keys turn the view (left, up)", dot(v1, right) < -1e-3 && v2[2] > v1[2] + 1e-3, `${fmt(v0)} -> ${fmt(v1)} -> ${fmt(v2)}`);
  const fa = Number((await ds(page)).fov), fb = Number((await press("+")).fov), fc = Number((await press("-")).fov);
  check("bricks: keys + and - narrow and widen the field of view", fb < fa && fc > fb, `${fa} -> ${fb} -> ${fc}`);
  await page.evaluate(() => window.genbspView.setView([0.9, 0.1, 0.3], 40));
  await press("2");
  const r = await press("r"), home = await view();
  const [hp] = locateAll(small, [home]);
  check("bricks: key R goes back to the first view", r.projection === "perspective" && angle(home, first.dir) < 1e-9 &&
    Math.abs(Number(r.fov) - first.fov) < 1e-3 && r.centerPolygon === String(hp),
    `${r.projection} ${r.fov} deg, ${fmt(home)} (first ${fmt(first.dir)}, ${first.fov} deg), centre ${r.centerPolygon}, genbsp locate ${hp}`);
  await page.evaluate(() => window.genbspView.setView([0.5, -0.3, 0.8], 90));
  const target = await page.evaluate(() => window.genbspView.directionAt(700, 250));
  await page.mouse.dblclick(700, 250);
  await settled(page);
  const looked = await view(), dd = await ds(page), [tp] = locateAll(small, [target]);
  check("bricks: a double-click looks there", angle(looked, target) < 1e-9 && dd.centerPolygon === String(tp),
    `${fmt(looked)}, wanted ${fmt(target)}; centre ${dd.centerPolygon}, genbsp locate ${tp}`);
  await press("Escape");
  const shownHelp = () => page.evaluate(() => getComputedStyle(document.getElementById("help")).display !== "none");
  await press("h");
  const h1 = await shownHelp();
  await press("h");
  check("bricks: key H shows and hides the help", h1 && !(await shownHelp()));
  await page.click("#btn-help");
  const h2 = await shownHelp();
  await page.click("#btn-help");
  check("bricks: the ? button shows and hides the help", h2 && !(await shownHelp()));
}

// The drawing, pixel by pixel, in every projection.
await pixelChecks(small, page, VIEWS, 40, 28);

// Save SVG: a download of an SVG that draws what the canvas draws.
{
  await page.evaluate(() => window.genbspView.setView([0.2, -0.4, 0.9], 100));
  const [download] = await Promise.all([page.waitForEvent("download", { timeout: 60000 }), page.click("#btn-svg")]);
  const path = join(work, "saved.svg");
  await download.saveAs(path);
  const svg = readFileSync(path, "utf8");
  const drawn = Number((await ds(page)).facesDrawn);
  const parsed = await page.evaluate((text) => {
    const doc = new DOMParser().parseFromString(text, "image/svg+xml");
    return { error: !!doc.querySelector("parsererror"), root: doc.documentElement.localName, faces: doc.querySelectorAll("path[data-polygon]").length,
      paths: doc.querySelectorAll("path").length };
  }, svg);
  check("bricks: Save SVG downloads an SVG of the faces drawn", !parsed.error && parsed.root === "svg" && parsed.faces === drawn && drawn > 0 &&
    parsed.paths > drawn && /\.svg$/.test(download.suggestedFilename()),
    `${download.suggestedFilename()}: ${parsed.faces} face paths (${parsed.paths} paths in all), ${drawn} faces drawn`);
  // Rasterise it in the page with id colours and compare with the canvas.
  const ncol = Math.max(0, ...small.map.faces.map((f) => f.polygon)) + 1;
  const ids = Array.from({ length: ncol }, (_, p) => "#" + (p + 1).toString(16).padStart(6, "0"));
  await page.evaluate((ids) => window.genbspView.setOptions({ edges: false, overlay: false, colours: ids, background: "#000000" }), ids);
  const samples = interior(small, await sampleGrid(page, 30, 20));
  const r = await page.evaluate(async (pts) => {
    const text = window.genbspView.svg();
    const bad = new DOMParser().parseFromString(text, "image/svg+xml").querySelector("parsererror");
    const img = new Image();
    img.src = URL.createObjectURL(new Blob([text], { type: "image/svg+xml" }));
    await img.decode();
    const c = document.createElement("canvas");
    c.width = innerWidth; c.height = innerHeight;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    return { parsed: !bad, px: pts.map(([x, y]) => Array.from(g.getImageData(Math.floor(x), Math.floor(y), 1, 1).data)) };
  }, samples.map((s) => [s.x, s.y]));
  const differ = samples.filter((s, i) => !closeRGB(r.px[i], rgbHex(s.rgb)));
  check("bricks: the SVG parses and draws what the canvas draws", r.parsed && samples.length >= 10 && differ.length === 0,
    `${samples.length - differ.length}/${samples.length} pixels agree` + (differ.length ? `; first at (${differ[0].x},${differ[0].y})` : ""));
  await page.evaluate(() => window.genbspView.setOptions({ edges: true, overlay: true, colours: null, background: null }));
}

// The page's making: `genbsp view` and web/embed.mjs put the map and the
// colours in place of the placeholders of web/viewer.html, and nothing else.
{
  const template = readFileSync(join(web, "viewer.html"), "utf8");
  const sameMap = (a, b) => JSON.stringify([a.eye, a.vertices, a.faces]) === JSON.stringify([b.eye, b.vertices, b.faces]);
  const embedded = join(work, "embedded.html");
  execFileSync("node", [join(web, "embed.mjs"), join(work, "bricks12.json"), "-o", embedded]);
  const e = unembed(readFileSync(embedded, "utf8"));
  check("web/embed.mjs writes web/viewer.html with the map in place", e !== null && e.template === template && sameMap(e.map, small.map) && e.colors === null);
  if (hasView) {
    const viewed = join(work, "viewed.html");
    run(["view", small.off, "--eye", small.eye, "-o", viewed]);
    const v = unembed(readFileSync(viewed, "utf8"));
    const nulls = v && Array.isArray(v.colors) && v.colors.every((x) => x === null);
    const same = v !== null && v.template === template;
    if (same || useView)
      check("genbsp view writes web/viewer.html with the map in place", same && sameMap(v.map, small.map) && nulls,
        same ? "" : "its copy of web/viewer.html differs from the file (rebuild genbsp)");
    else skip("genbsp view writes web/viewer.html", "its copy of web/viewer.html differs from the file (GENBSP_VIEWER_EMBED is set; rebuild genbsp)");
  } else skip("genbsp view writes web/viewer.html", "this genbsp has no view subcommand");
}

// Colours embedded with the map: each polygon drawn in its colour (null
// entries and polygons past the end in the palette's), as genbsp locate says.
{
  const ncol = Math.max(0, ...small.map.faces.map((f) => f.polygon)) + 1;
  const colors = Array.from({ length: ncol - 2 }, (_, p) => (p % 4 === 3 ? null
    : "#" + [(p * 67 + 20) % 256, (p * 131 + 80) % 256, (p * 29 + 160) % 256].map((v) => v.toString(16).padStart(2, "0")).join("")));
  const colorsPath = join(work, "colors.json"), html = join(work, "coloured.html");
  writeFileSync(colorsPath, JSON.stringify(colors));
  execFileSync("node", [join(web, "embed.mjs"), join(work, "bricks12.json"), "--colors", colorsPath, "-o", html]);
  const p = await open({ ...small, html });
  await p.evaluate(async (d) => { await window.genbspView.setOptions({ overlay: false }); await window.genbspView.setView(d, 110); }, [0.1, -0.3, 0.95]);
  const samples = interior(small, await sampleGrid(p, 30, 20));
  const polys = locateAll(small, samples.map((s) => s.d));
  const palette = new Map(await p.evaluate((ps) => ps.map((q) => [q, window.genbspView.colourOf(q)]), [...new Set(polys)]));
  const bad = [];
  let own = 0, fallback = 0;
  samples.forEach((s, i) => {
    const q = polys[i], want = q < 0 ? "#ffffff" : colors[q] || palette.get(q);
    if (q >= 0 && colors[q]) own++; else if (q >= 0) fallback++;
    if (!closeRGB(s.rgb, want)) bad.push(`(${s.x},${s.y}) polygon ${q}: ${rgbHex(s.rgb)} not ${want}`);
  });
  check("bricks: embedded colours: pixels show their polygon's colour", bad.length === 0 && own >= 10 && fallback >= 1,
    `${samples.length} pixels, ${own} in embedded colours, ${fallback} in the palette` + (bad.length ? "; " + bad.slice(0, 3).join("; ") : ""));
  await p.close();
}

// Shadows: `genbsp view --light` lists the lights reaching each face; the
// page draws the faces no light reaches at 35 % of their colour.
if (useView) {
  const html = join(work, "lit.html");
  run(["view", small.off, "--eye", small.eye, "--light", "13/3,-5/2,1", "-o", html]);
  const lit = unembed(readFileSync(html, "utf8"));
  const scene = { ...small, html, map: lit.map, geo: geometry(lit.map) };
  const p = await open(scene);
  await p.evaluate(async (d) => { await window.genbspView.setOptions({ overlay: false, edges: false }); await window.genbspView.setView(d, 110); }, [0.1, -0.3, 0.95]);
  const samples = interior(scene, await sampleGrid(p, 40, 28));
  const faces = await p.evaluate((ds) => ds.map((d) => window.genbspView.locate(d).face), samples.map((s) => s.d));
  const palette = new Map(await p.evaluate((ps) => ps.map((q) => [q, window.genbspView.colourOf(q)]), [...new Set(faces.map((f) => lit.map.faces[f].polygon))]));
  const dim = (hex) => "#" + [1, 3, 5].map((k) => Math.round(parseInt(hex.slice(k, k + 2), 16) * 0.35).toString(16).padStart(2, "0")).join("");
  const bad = [];
  let dark = 0, bright = 0;
  samples.forEach((s, i) => {
    const f = lit.map.faces[faces[i]];
    if (f.polygon < 0) return;
    const inShadow = Array.isArray(f.lights) && f.lights.length === 0, want = inShadow ? dim(palette.get(f.polygon)) : palette.get(f.polygon);
    inShadow ? dark++ : bright++;
    if (!closeRGB(s.rgb, want)) bad.push(`(${s.x},${s.y}) polygon ${f.polygon}${inShadow ? " in shadow" : ""}: ${rgbHex(s.rgb)} not ${want}`);
  });
  check("bricks: shadows: faces no light reaches are drawn dark, the others in their colour",
    bad.length === 0 && dark >= 10 && bright >= 10, `${dark} pixels in shadow, ${bright} lit` + (bad.length ? "; " + bad.slice(0, 3).join("; ") : ""));
  check("bricks: shadows: every face of the lit map lists its lights", lit.map.faces.every((f) => f.polygon < 0 || Array.isArray(f.lights)));
  await p.close();
}

// The URL's fragment sets the first view; Reset goes back to it.
{
  const dir = unit([0.4, -0.2, 0.85]);
  const p = await open(small, `#proj=fisheye&fov=150&dir=${dir.join(",")}`);
  const v = await p.evaluate(() => ({ dir: window.genbspView.viewDirection(), projection: window.genbspView.projection(), fov: window.genbspView.fov() }));
  const [c] = locateAll(small, [v.dir]);
  check("bricks: #proj=fisheye&fov=150&dir=... opens that view", v.projection === "fisheye" && Math.abs(v.fov - 150) < 1e-9 && angle(v.dir, dir) < 1e-9 &&
    (await ds(p)).centerPolygon === String(c), `${v.projection} ${v.fov} deg ${fmt(v.dir)}`);
  await p.evaluate(async () => { await window.genbspView.setProjection("perspective"); await window.genbspView.setView([1, 0, 0], 50); });
  await p.click("#btn-reset");
  await settled(p);
  const r = await p.evaluate(() => ({ dir: window.genbspView.viewDirection(), projection: window.genbspView.projection(), fov: window.genbspView.fov() }));
  check("bricks: the Reset button goes back to it", r.projection === "fisheye" && Math.abs(r.fov - 150) < 1e-9 && angle(r.dir, dir) < 1e-9,
    `${r.projection} ${r.fov} deg ${fmt(r.dir)}`);
  await p.close();
}

// web/viewer.html itself, with no map: it takes a MAP.json chosen (or dropped) on the page.
{
  const p = await context.newPage();
  p.on("pageerror", (e) => consoleErrors.push(`viewer.html: ${e.message}`));
  await p.goto(pathToFileURL(join(web, "viewer.html")).href);
  const empty = await p.evaluate(() => ({ ready: document.body.dataset.ready, drop: getComputedStyle(document.getElementById("drop")).display }));
  check("web/viewer.html without a map asks for one", empty.ready === "false" && empty.drop !== "none", JSON.stringify(empty));
  await p.setInputFiles("#file", join(work, "bricks12.json"));
  await p.waitForFunction(() => document.body.dataset.ready === "true", null, { timeout: 30000 });
  const d = await ds(p), m = await p.evaluate(() => window.genbspView.map);
  const [c] = locateAll(small, [await p.evaluate(() => window.genbspView.viewDirection())]);
  check("web/viewer.html shows a MAP.json chosen on the page", m.faces === small.map.faces.length && d.centerPolygon === String(c),
    `${m.faces} faces, centre polygon ${d.centerPolygon}, genbsp locate ${c}`);
  await p.close();
}

// Pictures for docs/viewer.md (900 x 600): the furnished room where this
// genbsp has it, else platforms; web/viewer.html from disk, with the scene's
// colours as `genbsp view` finds them.
if (SHOTS) {
  mkdirSync(SHOTS, { recursive: true });
  const room = /\broom\b/.test(spawnSync(genbsp, ["scene", "--help"], { encoding: "utf8" }).stdout || "");
  const sc = room ? { family: "room", n: 1 } : { family: "platforms", n: 12 };
  const off = join(work, `${sc.family}.off`), html = join(work, `${sc.family}.html`);
  const eye = run(["scene", sc.family, "--n", String(sc.n), "-o", off]).trim();
  const mapPath = join(work, `${sc.family}.json`), colorsPath = join(work, `${sc.family}-colors.json`);
  run(["map", off, "--eye", eye, "-o", mapPath]);
  const colors = [];
  if (hasView) {
    run(["view", off, "--eye", eye, "-o", html]);
    colors.push("--colors", colorsPath);
    writeFileSync(colorsPath, JSON.stringify(unembed(readFileSync(html, "utf8")).colors));
  }
  execFileSync("node", [join(web, "embed.mjs"), mapPath, ...colors, "-o", html]);
  const p = await open({ family: sc.family, html });
  await p.setViewportSize({ width: 900, height: 600 });
  await settled(p);
  // The room: look at the table as docs/rendering.md does; platforms: the first view.
  const e = eye.split(",").map((t) => t.split("/").reduce((x, y) => Number(x) / Number(y)));
  const look = room ? unit([330 - e[0], 250 - e[1], 80 - e[2]]) : await p.evaluate(() => window.genbspView.viewDirection());
  const level = room ? [1, 0.2, 0] : [1, 0, 0];
  for (const [name, setup] of [["perspective", { projection: "perspective", fov: 90, dir: look }],
    ["stereographic", { projection: "stereographic", fov: 200, dir: look }], ["fisheye", { projection: "fisheye", fov: 250, dir: look }],
    ["equirectangular", { projection: "equirectangular", fov: 360, dir: level }], ["globe", { projection: "perspective", fov: 90, dir: look, globe: true }]]) {
    await p.evaluate(async (s) => {
      const g = window.genbspView;
      await g.setMode("observer"); await g.setProjection(s.projection); await g.setFov(s.fov); await g.setView(s.dir);
      if (s.globe) await g.setMode("globe");
    }, setup);
    if (name === "perspective") { await p.mouse.click(room ? 505 : 500, room ? 300 : 340); await settled(p); }
    if (name === "globe") await drag(p, 450, 300, 120, -50);
    await p.screenshot({ path: join(SHOTS, `viewer-${name}.png`) });
  }
  info(`pictures of ${sc.family} (eye ${eye}, looking along ${fmt(look)}) saved in ${SHOTS}`);
  await p.close();
}
await page.close();

// A map of at least 10,000 faces: correctness in every projection.  The
// frame times are printed for information only; a speed target is the
// viewer benchmark's (bench/viewer.mjs), never a check here.
{
  const t0 = Date.now();
  const big = makeScene("terrain", 100);
  info(`large scene: terrain --n 100, eye ${big.eye}, ${big.map.faces.length} faces (map and page in ${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  check("terrain: the map has at least 10,000 faces", big.map.faces.length >= 10000, `${big.map.faces.length}`);
  const p = await open(big);
  const frames = [];
  for (const [name, setup] of [["perspective", {}], ["stereographic", { fov: 180 }], ["fisheye", { fov: 200 }],
    ["equirectangular", { fov: 360 }], ["globe", { mode: "globe" }]]) {
    const r = await p.evaluate(async ([name, s]) => {
      const g = window.genbspView;
      await g.setMode("observer");
      if (name !== "globe") { await g.setProjection(name); if (s.fov) await g.setFov(s.fov); } else await g.setMode("globe");
      return g.benchmark(20, 0.5);
    }, [name, setup]);
    frames.push(`${name} ${r.intervalMs.toFixed(1)} ms (drawing code ${r.drawMs.toFixed(1)} ms, ${r.facesDrawn} faces)`);
  }
  info(`frame times (information only), ${big.map.faces.length} faces, 1100x760: ${frames.join(", ")}`);
  await p.evaluate(() => window.genbspView.setMode("observer"));
  await p.evaluate(() => window.genbspView.setProjection("perspective"));
  await pixelChecks(big, p, VIEWS.filter((v) => !v.dir || v.projection === "equirectangular"), 28, 20);
  await p.close();
}

check("no console errors or page errors", consoleErrors.length === 0, consoleErrors.slice(0, 3).join(" | "));
check("no network requests", blocked.length === 0, blocked.slice(0, 3).join(" "));
await browser.close();
info(`${skipped} skipped; ${((Date.now() - started) / 1000).toFixed(1)} s`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
