#!/usr/bin/env node
// Frame rate of the browser viewer (web/viewer.html, as `genbsp view` writes
// it) in headless Chromium: for each scene and projection, the view turns
// by half a degree a frame for several seconds, and the median time between
// frames (requestAnimationFrame, so the browser's rasterising counts) and
// the median time of the page's own drawing code are reported.
//
// Usage: node bench/viewer.mjs [options]      (see --help)
//
// Needs node, Debian's chromium and the npm package playwright-core, which
// `scripts/test` installs into build/release/viewer-work.  Results go to a
// JSON file; with --update FILE the part of FILE between its viewer-report
// markers is rewritten (docs/benchmarks.md), and --plot writes a bar chart.
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, renameSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { cpus, loadavg, totalmem } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const defaults = {
  genbsp: join(root, "build/release/tools/genbsp"),
  work: join(root, "build/bench-viewer"),
  "node-modules": join(root, "build/release/viewer-work"),
  chromium: "/usr/bin/chromium",
  scenes: "terrain:100,sphere:113",
  seconds: "4",
  size: "1100x760",
  json: "",
  update: "",
  plot: "",
};
const HELP = `usage: node bench/viewer.mjs [--OPTION VALUE ...]

Times the browser viewer's frames in headless Chromium, per scene and
projection (perspective, stereographic 180, fisheye 200, equirectangular
panorama, globe): median frame interval and median drawing time over
--seconds of frames while the view turns.

  --genbsp PATH        the genbsp program (${defaults.genbsp})
  --work DIR           scratch folder for scenes, maps and pages (${defaults.work})
  --node-modules DIR   where playwright-core is installed (${defaults["node-modules"]})
  --chromium PATH      Chromium binary (${defaults.chromium})
  --scenes LIST        FAMILY:N,... of \`genbsp scene\` (${defaults.scenes})
  --seconds S          seconds of frames per projection, after 10 warm-up frames (${defaults.seconds})
  --size WxH           window size (${defaults.size})
  --json FILE          write the results as JSON
  --update FILE        rewrite FILE between <!-- viewer-report:begin --> and <!-- viewer-report:end -->
  --plot FILE          write a bar chart of the frame times as SVG
  --quick              smoke run: terrain:30, 1 second each

Exit status: 0 done, 2 bad arguments or a failed step, 77 playwright-core or
Chromium missing.
`;

function fail(message) {
  process.stderr.write(`bench/viewer.mjs: ${message}\n`);
  process.exit(2);
}

const args = { ...defaults };
for (let i = 2; i < process.argv.length; i++) {
  const a = process.argv[i];
  if (a === "-h" || a === "--help") { process.stdout.write(HELP); process.exit(0); }
  if (a === "--quick") { args.scenes = "terrain:30"; args.seconds = "1"; continue; }
  const key = a.replace(/^--/, "");
  if (!a.startsWith("--") || !(key in defaults)) fail(`unknown argument '${a}' (try --help)`);
  if (i + 1 >= process.argv.length) fail(`${a} needs a value`);
  args[key] = process.argv[++i];
}
const seconds = Number(args.seconds);
if (!(seconds > 0)) fail(`--seconds must be a positive number, not '${args.seconds}'`);
const size = /^(\d+)x(\d+)$/.exec(args.size);
if (!size) fail(`--size must be WxH, not '${args.size}'`);
const viewport = { width: Number(size[1]), height: Number(size[2]) };
const scenes = args.scenes.split(",").map((s) => {
  const m = /^([a-z-]+):(\d+)$/.exec(s.trim());
  if (!m) fail(`--scenes takes FAMILY:N,..., not '${s}'`);
  return { family: m[1], n: Number(m[2]) };
});

let chromium;
try {
  ({ chromium } = createRequire(join(resolve(args["node-modules"]), "x.js"))("playwright-core"));
} catch {
  process.stderr.write(`bench/viewer.mjs: playwright-core is not installed in ${args["node-modules"]} (npm install --prefix ${args["node-modules"]} playwright-core)\n`);
  process.exit(77);
}
if (!existsSync(args.chromium)) {
  process.stderr.write(`bench/viewer.mjs: no Chromium at ${args.chromium} (apt-get install chromium)\n`);
  process.exit(77);
}
const genbsp = resolve(args.genbsp), work = resolve(args.work);
mkdirSync(work, { recursive: true });
const run = (argv) => execFileSync(genbsp, argv, { encoding: "utf8", maxBuffer: 1 << 30 });
const progress = (line) => process.stderr.write(`${line}\n`);

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b), k = s.length >> 1;
  return s.length % 2 ? s[k] : (s[k - 1] + s[k]) / 2;
};
const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];

/** Degrees the view turns a frame. */
const STEP = 0.02;
const PROJECTIONS = [["perspective", {}], ["stereographic", { fov: 180 }], ["fisheye", { fov: 200 }],
  ["equirectangular", { fov: 360 }], ["globe", { globe: true }]];

const started = new Date(), load0 = loadavg()[0];
let commit = "unknown";
try { commit = execFileSync("git", ["-C", root, "describe", "--always", "--dirty"], { encoding: "utf8" }).trim(); } catch {}
const browser = await chromium.launch({ executablePath: args.chromium, headless: true, args: ["--no-sandbox"] });
const context = await browser.newContext({ viewport, offline: true });
const results = [];
try {
  for (const sc of scenes) {
    const base = join(work, `${sc.family}${sc.n}`);
    const eye = run(["scene", sc.family, "--n", String(sc.n), "-o", `${base}.off`]).trim();
    const t0 = Date.now();
    run(["view", `${base}.off`, "--eye", eye, "-o", `${base}.html`]);
    const viewSeconds = (Date.now() - t0) / 1000;
    const header = readFileSync(`${base}.off`, "utf8").replace(/#[^\n]*/g, "");
    const triangles = Number(/^\s*OFF\s+(\d+)\s+(\d+)/.exec(header)?.[2] ?? NaN);
    const page = await context.newPage();
    const errors = [];
    page.on("pageerror", (e) => errors.push(e.message));
    await page.goto(pathToFileURL(`${base}.html`).href);
    await page.waitForFunction(() => document.body.dataset.ready === "true", null, { timeout: 600000 });
    const faces = await page.evaluate(() => window.genbspView.map.faces);
    // Every projection starts from the page's first view (towards what is
    // visible, framed in perspective) and turns slowly, so that what it
    // draws stays in view.
    const home = await page.evaluate(() => window.genbspView.viewDirection());
    progress(`${sc.family} --n ${sc.n}: ${triangles} input faces, map of ${faces} faces (genbsp view ${viewSeconds.toFixed(1)} s)`);
    for (const [name, s] of PROJECTIONS) {
      const r = await page.evaluate(async ([name, s, seconds, home, STEP]) => {
        const g = window.genbspView;
        await g.setMode("observer");
        await g.setProjection(s.globe ? "perspective" : name);
        await g.setView(home);
        if (s.fov) await g.setFov(s.fov);
        if (s.globe) await g.setMode("globe");
        await g.benchmark(10, STEP);
        return g.benchmark(30, STEP, seconds);
      }, [name, s, seconds, home, STEP]);
      const row = {
        scene: `${sc.family} --n ${sc.n}`, input_faces: triangles, map_faces: faces, projection: name,
        frames: r.frames, faces_drawn: r.facesDrawn,
        median_frame_ms: median(r.intervals), p90_frame_ms: quantile(r.intervals, 0.9),
        median_draw_ms: median(r.draws), fps: 1000 / median(r.intervals), mean_fps: r.fps,
      };
      results.push(row);
      progress(`  ${name}: ${row.fps.toFixed(1)} fps, mean ${row.mean_fps.toFixed(1)} (median ${row.median_frame_ms.toFixed(1)} ms, drawing code ${row.median_draw_ms.toFixed(1)} ms, ${row.faces_drawn} faces drawn, ${row.frames} frames)`);
    }
    if (errors.length) fail(`${sc.family}: page errors: ${errors.slice(0, 3).join(" | ")}`);
    await page.close();
  }
} finally {
  await browser.close().catch(() => {});
}

const machine = {
  cpu: cpus()[0]?.model ?? "unknown", threads: cpus().length, memory_gib: Math.round(totalmem() / 2 ** 30),
  chromium: browser.version(), node: process.version, commit,
  started: started.toISOString(), minutes: (Date.now() - started) / 60000, load_start: load0, load_end: loadavg()[0],
  window: args.size, seconds_per_projection: seconds,
};

/** Writes `text` to `path` whole or not at all. */
function writeWhole(path, text) {
  const tmp = `${path}.tmp${process.pid}`;
  writeFileSync(tmp, text);
  renameSync(tmp, path);
}

const TARGET_FPS = 30, TARGET_FACES = 10000;
function report() {
  const lines = [
    "",
    "### Machine",
    "",
    `* ${machine.threads} hardware threads, CPU \`${machine.cpu}\`, ${machine.memory_gib} GiB memory`,
    `* Chromium ${machine.chromium} (headless, software rendering), node ${machine.node}; window ${machine.window}`,
    `* source: \`${machine.commit}\`; run started ${machine.started.replace(/\.\d+Z$/, "Z")}, ${machine.minutes.toFixed(1)} min in all; load average ${machine.load_start.toFixed(2)} at the start, ${machine.load_end.toFixed(2)} at the end`,
    `* ${machine.seconds_per_projection} s of frames per projection after 10 warm-up frames`,
    "",
    "### Results",
    "",
    "| Scene | Input faces | Map faces | Projection | Faces drawn | fps (median frame) | fps (mean) | Frame, median (ms) | Frame, 90th percentile (ms) | Drawing code, median (ms) | Frames |",
    "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|",
    ...results.map((r) => `| ${r.scene} | ${r.input_faces.toLocaleString("en-US")} | ${r.map_faces.toLocaleString("en-US")} | ${r.projection} | ${r.faces_drawn.toLocaleString("en-US")} | ${r.fps.toFixed(1)} | ${r.mean_fps.toFixed(1)} | ${r.median_frame_ms.toFixed(1)} | ${r.p90_frame_ms.toFixed(1)} | ${r.median_draw_ms.toFixed(1)} | ${r.frames} |`),
    "",
  ];
  const judged = results.filter((r) => r.projection === "perspective" && r.faces_drawn >= TARGET_FACES);
  lines.push(`Target: at least ${TARGET_FPS} fps in perspective with at least ${TARGET_FACES.toLocaleString("en-US")} faces drawn.`);
  if (judged.length === 0) lines.push("No perspective row of this run draws that many faces, so the target is not judged.");
  for (const r of judged) lines.push(`* ${r.scene}: ${r.fps.toFixed(1)} fps with ${r.faces_drawn.toLocaleString("en-US")} faces drawn: target ${r.fps >= TARGET_FPS ? "met" : "missed"}.`);
  lines.push("");
  return lines.join("\n");
}

/** A horizontal bar chart of the median frame times, one bar per scene and projection. */
function plot() {
  const bar = 16, gap = 6, left = 260, width = 420, top = 30;
  const maxMs = Math.max(...results.map((r) => r.median_frame_ms), 1000 / TARGET_FPS) * 1.05;
  const x = (ms) => left + (width * ms) / maxMs;
  const h = top + results.length * (bar + gap) + 40;
  const esc = (s) => s.replace(/&/g, "&amp;").replace(/</g, "&lt;");
  const out = [`<svg xmlns="http://www.w3.org/2000/svg" width="${left + width + 90}" height="${h}" font-family="sans-serif" font-size="12">`,
    `<text x="${left}" y="18">median frame time (ms), window ${esc(machine.window)}; dashed: ${TARGET_FPS} fps</text>`];
  results.forEach((r, i) => {
    const y = top + i * (bar + gap);
    out.push(`<text x="${left - 6}" y="${y + bar - 4}" text-anchor="end">${esc(`${r.scene}, ${r.projection}`)}</text>`);
    out.push(`<rect x="${left}" y="${y}" width="${(x(r.median_draw_ms) - left).toFixed(1)}" height="${bar}" fill="#4a7ab0"/>`);
    out.push(`<rect x="${x(r.median_draw_ms).toFixed(1)}" y="${y}" width="${Math.max(0, x(r.median_frame_ms) - x(r.median_draw_ms)).toFixed(1)}" height="${bar}" fill="#a8c4e0"/>`);
    out.push(`<text x="${(x(r.median_frame_ms) + 4).toFixed(1)}" y="${y + bar - 4}">${r.median_frame_ms.toFixed(1)}</text>`);
  });
  const yEnd = top + results.length * (bar + gap);
  out.push(`<line x1="${x(1000 / TARGET_FPS).toFixed(1)}" y1="${top - 4}" x2="${x(1000 / TARGET_FPS).toFixed(1)}" y2="${yEnd}" stroke="#c03030" stroke-dasharray="4 3"/>`);
  out.push(`<rect x="${left}" y="${yEnd + 10}" width="12" height="12" fill="#4a7ab0"/><text x="${left + 16}" y="${yEnd + 21}">the page's drawing code</text>`);
  out.push(`<rect x="${left + 180}" y="${yEnd + 10}" width="12" height="12" fill="#a8c4e0"/><text x="${left + 196}" y="${yEnd + 21}">the rest of the frame (rasterising)</text>`);
  out.push("</svg>");
  return out.join("\n") + "\n";
}

const text = report();
process.stdout.write(text);
if (args.json) writeWhole(args.json, JSON.stringify({ machine, results }, null, 1) + "\n");
if (args.plot) writeWhole(args.plot, plot());
if (args.update) {
  const doc = readFileSync(args.update, "utf8");
  const begin = "<!-- viewer-report:begin -->", end = "<!-- viewer-report:end -->";
  const a = doc.indexOf(begin), b = doc.indexOf(end);
  if (a < 0 || b < a) fail(`${args.update} has no ${begin} ... ${end} section`);
  writeWhole(args.update, doc.slice(0, a + begin.length) + "\n" + text + doc.slice(b));
}
