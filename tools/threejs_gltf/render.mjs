#!/usr/bin/env node
// Renders one glTF with three.js's own renderer (GLTFLoader, its MeshStandard/Physical
// materials, the environment through PMREMGenerator as scene.environment, no background), the
// way model-viewer shows a model, in headless Chromium (WebGL2 on SwiftShader): the three.js
// peer of the glTF Render Fidelity benchmark (issue 38; /work/fidelity_spec.md's view spec).
//
//   node tools/threejs_gltf/render.mjs SPEC.json OUT
//
// SPEC.json: {"gltf": "/abs/model.glb", "environment": "/abs/sky.exr" (linear equirect in
//             pbrlab's convention) or null, "size": [w, h],
//             "camera": {"eye": [x, y, z], "target": [x, y, z], "up": [0, 1, 0],
//                        "yfov_deg": 45, "znear": n, "zfar": f},
//             optional: "msaa": 4 (the float target's samples; 0 for none),
//             "environmentIntensity": 1, "threejsEnvironmentRotationDeg": -90,
//             "transmissionBackground": [r, g, b] (a constant sky's linear colour: what glass
//             over nothing shows, in place of three.js's white; page/peer.mjs),
//             "capturePrograms": true (also OUT.programs.json: every WebGL2 program the page
//             linked, its sources and draw count; ../chromium/program_capture.mjs)}
// Other keys of the shared view spec (environment_hdr, samples, seed, denoise) are ignored.
// Writes OUT.f32 (float32 RGBA, rows top to bottom, linear radiance, NOT premultiplied:
// three.js's premultiplied colour divided by alpha where alpha > 0; alpha = coverage) and
// OUT.json (size, WebGL renderer, three.js revision, multisampling, timings, console messages).
// Chromium's start-up and the page's server: tools/chromium/launch.mjs.
import { writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { rowsTopDown, runPage, runTool } from "../chromium/launch.mjs";
import { capturedPrograms, installProgramCapture } from "../chromium/program_capture.mjs";

const HERE = dirname(fileURLToPath(import.meta.url));
const THREE_DIR = join(HERE, "node_modules", "three");
const PAGE = join(HERE, "page");
// three.js samples its environment at u = pbrlab's u + 1/4 (see page/peer.mjs for the
// derivation from three.js's source); this rotation about +Y removes the quarter turn.
// Checked by pbrlab.checking.fidelity.check_staging (mirror and diffuse spheres).
const ENVIRONMENT_ROTATION_DEG = -90.0;

// /three/* -> node_modules/three, /page/* -> page/, /fs/ABS -> ABS when under an allowed root
function servedFile(path, allowedRoots) {
  if (path.startsWith("/three/")) {
    const abs = resolve(join(THREE_DIR, path.slice(7)));
    return abs.startsWith(THREE_DIR + "/") ? abs : null;
  }
  if (path.startsWith("/page/")) {
    const abs = resolve(join(PAGE, path.slice(6)));
    return abs.startsWith(PAGE + "/") ? abs : null;
  }
  if (path.startsWith("/fs/")) {
    const abs = resolve("/" + path.slice(4));
    if (allowedRoots.some((root) => abs.startsWith(root + "/"))) return abs;
  }
  return null;
}

function checkSpec(spec) {
  if (typeof spec.gltf !== "string") throw new Error("spec.gltf (the model's absolute path) is missing");
  if (!Array.isArray(spec.size) || spec.size.length !== 2 || !spec.size.every((n) => Number.isInteger(n) && n > 0))
    throw new Error("spec.size must be [width, height] in pixels");
  const c = spec.camera || {};
  for (const key of ["eye", "target", "up"])
    if (!Array.isArray(c[key]) || c[key].length !== 3) throw new Error(`spec.camera.${key} must be [x, y, z]`);
  for (const key of ["yfov_deg", "znear", "zfar"])
    if (typeof c[key] !== "number" || !(c[key] > 0)) throw new Error(`spec.camera.${key} must be a positive number`);
  if (spec.environment && !/\.exr$/i.test(spec.environment))
    throw new Error(`${spec.environment}: the three.js peer reads the spec's OpenEXR environment (EXRLoader)`);
}

// three.js's target holds premultiplied colour (page/peer.mjs); the shared output is not.
function unpremultiply(rows) {
  let partial = 0;
  for (let i = 0; i < rows.length; i += 4) {
    const a = rows[i + 3];
    if (a > 0) {
      rows[i] /= a;
      rows[i + 1] /= a;
      rows[i + 2] /= a;
      if (a < 1) partial++;
    }
  }
  return partial;
}

async function main(spec, outPrefix) {
  checkSpec(spec);
  const t0 = Date.now();
  const roots = [dirname(resolve(spec.gltf))];
  if (spec.environment) roots.push(dirname(resolve(spec.environment)));
  let t1 = t0;
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => servedFile(path, roots),
    page: "/page/index.html",
  }, async (page, base) => {
    t1 = Date.now();
    const pageSpec = {
      gltf: `${base}/fs${resolve(spec.gltf)}`,
      environment: spec.environment ? `${base}/fs${resolve(spec.environment)}` : null,
      environmentIntensity: spec.environmentIntensity ?? 1.0,
      environmentRotationRad: (spec.threejsEnvironmentRotationDeg ?? ENVIRONMENT_ROTATION_DEG) * Math.PI / 180,
      size: spec.size, msaa: spec.msaa ?? 4, camera: spec.camera,
      transmissionBackground: spec.transmissionBackground ?? null,
    };
    if (spec.capturePrograms) await page.evaluate(installProgramCapture);
    const rendered = await page.evaluate((s) => window.renderGltf(s), pageSpec);
    return spec.capturePrograms ? { ...rendered, programs: await page.evaluate(capturedPrograms) } : rendered;
  });
  const t2 = Date.now();
  const [width, height] = spec.size;
  const rows = rowsTopDown(result.pixels, width, height);
  const partialCoverage = unpremultiply(rows);
  await writeFile(`${outPrefix}.f32`, Buffer.from(rows.buffer));
  if (spec.capturePrograms) await writeFile(`${outPrefix}.programs.json`, JSON.stringify(result.programs, null, 1));
  const { pixels, ...rest } = result;
  await writeFile(`${outPrefix}.json`, JSON.stringify({
    size: [width, height], renderer: rest.renderer, version: `three.js r${rest.three}`, three: rest.three,
    webgl_version: rest.version, msaa: { ...rest.msaa, pixels_with_partial_coverage: partialCoverage },
    alpha: "coverage; colour unpremultiplied (three.js's target holds premultiplied colour)",
    environment_rotation_deg: spec.threejsEnvironmentRotationDeg ?? ENVIRONMENT_ROTATION_DEG,
    environment_size: rest.environment_size, messages, page_seconds: rest.seconds,
    seconds: (Date.now() - t0) / 1000,
    seconds_parts: { startup: (t1 - t0) / 1000, render: (t2 - t1) / 1000 },
  }, null, 1));
}

runTool("render.mjs", main);
