#!/usr/bin/env node
// Writes a self-contained viewer page: web/viewer.html with a map written by
// `genbsp map` (and optionally per-polygon colours) put in place of its
// placeholders.  The same substitution as `genbsp view` (docs/viewer.md):
//
//   the text /*GENBSP_MAP*/null     -> the map, as one line of JSON
//   the text /*GENBSP_COLORS*/null  -> a JSON array of "#rrggbb" strings (or null) indexed by polygon, or null
//
// Each placeholder occurs exactly once in the viewer.  A "<" (only ever in a
// JSON string) is written \u003c, so the data cannot end the page's script.  The output is
// written whole or not at all (a temporary file renamed into place).
//
// Usage: node web/embed.mjs MAP.json -o VIEW.html [--colors COLORS.json] [--viewer VIEWER.html]
import { readFileSync, writeFileSync, renameSync, rmSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const MAP_PLACEHOLDER = "/*GENBSP_" + "MAP*/null";
const COLORS_PLACEHOLDER = "/*GENBSP_" + "COLORS*/null";

function usage(message) {
  if (message) process.stderr.write(`embed.mjs: ${message}\n`);
  process.stderr.write("usage: node web/embed.mjs MAP.json -o VIEW.html [--colors COLORS.json] [--viewer VIEWER.html]\n");
  process.exit(2);
}

/** Replaces the one occurrence of `placeholder` in `text` by `value` (no pattern characters interpreted). */
export function substitute(text, placeholder, value) {
  const at = text.indexOf(placeholder);
  if (at < 0 || text.indexOf(placeholder, at + 1) >= 0) throw new Error(`the viewer must contain ${placeholder} exactly once`);
  return text.slice(0, at) + value + text.slice(at + placeholder.length);
}

/** JSON text of `value` on one line, safe inside a <script> element. */
const scriptJSON = (value) => JSON.stringify(value).replace(/</g, "\\u003c");

/** The viewer page for map text `mapText` and colours text `colorsText` (or null). */
export function embed(viewerText, mapText, colorsText = null) {
  const map = JSON.parse(mapText); // must be JSON
  if (!map || !Array.isArray(map.vertices) || !Array.isArray(map.faces)) throw new Error("not a genbsp map (no vertices or faces)");
  let colors = null;
  if (colorsText !== null) {
    colors = JSON.parse(colorsText);
    if (colors !== null && !(Array.isArray(colors) && colors.every((x) => x === null || (typeof x === "string" && /^#[0-9a-fA-F]{6}$/.test(x)))))
      throw new Error('colours: expected an array of "#rrggbb" strings (or null entries)');
  }
  return substitute(substitute(viewerText, MAP_PLACEHOLDER, scriptJSON(map)), COLORS_PLACEHOLDER, scriptJSON(colors));
}

function main(argv) {
  let mapPath = null, out = null, colorsPath = null;
  let viewer = join(dirname(fileURLToPath(import.meta.url)), "viewer.html");
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === "-o" || a === "--output") out = argv[++i];
    else if (a === "--colors") colorsPath = argv[++i];
    else if (a === "--viewer") viewer = argv[++i];
    else if (a === "-h" || a === "--help") usage();
    else if (a.startsWith("-") && a !== "-") usage(`unknown option ${a}`);
    else if (mapPath === null) mapPath = a;
    else usage(`unexpected argument ${a}`);
  }
  if (!mapPath || !out) usage("MAP.json and -o VIEW.html are required");
  let page;
  try {
    const mapText = readFileSync(mapPath === "-" ? 0 : mapPath, "utf8");
    const colorsText = colorsPath ? readFileSync(colorsPath, "utf8") : null;
    page = embed(readFileSync(viewer, "utf8"), mapText, colorsText);
  } catch (e) {
    process.stderr.write(`embed.mjs: ${e.message}\n`);
    process.exit(2);
  }
  const tmp = `${out}.tmp${process.pid}`;
  try {
    writeFileSync(tmp, page);
    renameSync(tmp, out);
  } catch (e) {
    rmSync(tmp, { force: true });
    process.stderr.write(`embed.mjs: ${out}: ${e.message}\n`);
    process.exit(2);
  }
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) main(process.argv.slice(2));
