#!/usr/bin/env node
// Runs the three.js example (examples/threejs) in headless Chromium (WebGL2 on SwiftShader)
// and writes what it drew, for tests/examples/test_threejs_example.py.
//
//   node render.mjs SPEC.json OUT
//
// SPEC.json: {"scene": "/abs/scene.json", "library": "/abs/pbrlab_library.glsl",
//             "dfg": "/abs/pbrlab_dfg.exr"}
// Writes OUT.f32 (float32 RGBA, rows top to bottom, linear radiance; alpha 0 where no
// sphere) and OUT.json (size, WebGL renderer, three.js revision, console messages).
// With "show": true in SPEC.json it opens the page as a reader does (index.html, the spec's
// files served under the names README.md writes) and writes OUT.png (the canvas as shown)
// and OUT.json (its status line, console messages) instead.
// Chromium's start-up and the page's server: tools/chromium/launch.mjs.
import { writeFile } from "node:fs/promises";
import { basename, dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { rowsTopDown, runPage, runTool, screenshotView } from "../chromium/launch.mjs";

const HERE = dirname(fileURLToPath(import.meta.url));
const REPO = resolve(HERE, "..", "..");
// /examples/threejs/* and /tools/threejs/node_modules/* from the checkout; /fs/ABS: the spec's files
const ROOTS = [join(REPO, "examples", "threejs"), join(HERE, "node_modules")];

function servedFile(path, allowedFiles) {
  if (path.startsWith("/fs/")) {
    const abs = resolve("/" + path.slice(4));
    return allowedFiles.includes(abs) ? abs : null;
  }
  const abs = resolve(join(REPO, path));
  return ROOTS.some((root) => abs.startsWith(root + "/")) ? abs : null;
}

// The page as README.md has a reader open it: the spec's files at the names it writes.
async function show(files, outPrefix) {
  const named = { "scene.json": files[0], "pbrlab_library.glsl": files[1], "pbrlab_dfg.exr": files[2] };
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => (dirname(path) === "/examples/threejs" && named[basename(path)]) || servedFile(path, []),
    page: "/examples/threejs/index.html",
  }, (page) => screenshotView(page, `${outPrefix}.png`));
  await writeFile(`${outPrefix}.json`, JSON.stringify({ status: result, messages }, null, 1));
}

async function main(spec, outPrefix) {
  const files = ["scene", "library", "dfg"].map((key) => resolve(spec[key]));
  if (spec.show) return show(files, outPrefix);
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => servedFile(path, files),
    page: "/examples/threejs/index.html?test",
  }, async (page, base) => {
    const urls = { scene: `${base}/fs${files[0]}`, library: `${base}/fs${files[1]}`, dfg: `${base}/fs${files[2]}` };
    return page.evaluate(async (u) => {
      const r = await window.renderScene(u);
      const bytes = new Uint8Array(r.pixels.buffer);
      let binary = "";
      for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return { width: r.width, height: r.height, renderer: r.renderer, three: r.three, pixels: btoa(binary) };
    }, urls);
  });
  const { width, height } = result;
  await writeFile(`${outPrefix}.f32`, Buffer.from(rowsTopDown(result.pixels, width, height).buffer));
  await writeFile(`${outPrefix}.json`, JSON.stringify({ size: [width, height], renderer: result.renderer,
                                                        three: result.three, messages }, null, 1));
}

runTool("render.mjs", main);
