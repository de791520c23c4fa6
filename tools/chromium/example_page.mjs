// What the browser examples' render.mjs share (tools/threejs, tools/babylonjs): the example's
// page (examples/NAME/index.html) served from the checkout, run in headless Chromium, and what it
// drew written for the tests (tests/examples/browser_example.py reads it).
//
//   SPEC.json: {"scene": "/abs/scene.json", "library": "/abs/pbrlab_library.glsl",
//               "dfg": "/abs/pbrlab_dfg.exr"}
// Writes OUT.f32 (float32 RGBA, rows top to bottom, linear radiance; alpha 0 where no sphere) and
// OUT.json (size, WebGL renderer, the engine's version under its key, console messages). With
// "show": true in SPEC.json it opens the page as a reader does (index.html, the spec's files served
// under the names README.md writes) and writes OUT.png (the canvas as shown) and OUT.json (its
// status line, console messages) instead. The page's window.renderScene(urls) returns
// {width, height, renderer, pixels: Float32Array, [versionKey]}.
import { writeFile } from "node:fs/promises";
import { basename, dirname, join, resolve } from "node:path";
import { rowsTopDown, runPage, screenshotView } from "./launch.mjs";

const REPO = resolve(dirname(new URL(import.meta.url).pathname), "..", "..");

// chromium: the tool's playwright-core (resolved from its own node_modules); example: the folder
// name under examples/ and tools/; versionKey: the field naming the engine's version.
export async function runExample(chromium, { example, versionKey }, spec, outPrefix) {
  const pageDir = `/examples/${example}`;
  // /examples/NAME/* and /tools/NAME/node_modules/* from the checkout; /fs/ABS: the spec's files
  const roots = [join(REPO, "examples", example), join(REPO, "tools", example, "node_modules")];
  const files = ["scene", "library", "dfg"].map((key) => resolve(spec[key]));
  const servedFile = (path, allowedFiles) => {
    if (path.startsWith("/fs/")) {
      const abs = resolve("/" + path.slice(4));
      return allowedFiles.includes(abs) ? abs : null;
    }
    const abs = resolve(join(REPO, path));
    return roots.some((root) => abs.startsWith(root + "/")) ? abs : null;
  };
  if (spec.show) {
    const named = { "scene.json": files[0], "pbrlab_library.glsl": files[1], "pbrlab_dfg.exr": files[2] };
    const { result, messages } = await runPage(chromium, {
      resolveFile: (path) => (dirname(path) === pageDir && named[basename(path)]) || servedFile(path, []),
      page: `${pageDir}/index.html`,
    }, (page) => screenshotView(page, `${outPrefix}.png`));
    await writeFile(`${outPrefix}.json`, JSON.stringify({ status: result, messages }, null, 1));
    return;
  }
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => servedFile(path, files),
    page: `${pageDir}/index.html?test`,
  }, async (page, base) => {
    const urls = { scene: `${base}/fs${files[0]}`, library: `${base}/fs${files[1]}`, dfg: `${base}/fs${files[2]}` };
    return page.evaluate(async ([u, key]) => {
      const r = await window.renderScene(u);
      const bytes = new Uint8Array(r.pixels.buffer, r.pixels.byteOffset, r.pixels.byteLength);
      let binary = "";
      for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return { width: r.width, height: r.height, renderer: r.renderer, version: r[key], pixels: btoa(binary) };
    }, [urls, versionKey]);
  });
  const { width, height } = result;
  await writeFile(`${outPrefix}.f32`, Buffer.from(rowsTopDown(result.pixels, width, height).buffer));
  await writeFile(`${outPrefix}.json`, JSON.stringify({ size: [width, height], renderer: result.renderer,
                                                        [versionKey]: result.version, messages }, null, 1));
}
