#!/usr/bin/env node
// Renders one glTF file with the Khronos glTF Sample Renderer (npm @khronosgroup/gltf-viewer)
// in headless Chromium (WebGL2 on SwiftShader), pbrlab's second, independent glTF renderer.
//
//   node render.mjs SPEC.json OUT
//
// SPEC.json: {"gltf": "/abs/model.gltf", "size": [w, h],
//             "camera": {"cameraToWorld": [16 numbers, column-major], "yfovRad": r,
//                        "znear": n, "zfar": f}  or  {"index": glTF camera index}
//                       or the fidelity benchmark's view spec form (/work/fidelity_spec.md)
//                        {"eye": [x, y, z], "target": [x, y, z], "up": [x, y, z],
//                         "yfov_deg": d, "znear": n, "zfar": f},
//             "environment": "/abs/sky.hdr" or null (punctual lights only),
//             "environment_hdr": "/abs/sky.hdr" (the view spec's .hdr twin: read instead of
//                        "environment", which is then the spec's .exr),
//             "environmentIntensity": 1, "environmentRotationDeg": 90,
//             "msaa": 0 (or 4: the float target multisampled and resolved),
//             "unpremultiply": false (true: colour divided by alpha where 0 < alpha),
//             "iblSampler": {"lambertianSampleCount": 2048, ...} (see IBL_SAMPLER_SETTINGS),
//             "capturePrograms": true (also OUT.programs.json: every WebGL2 program the page
//             linked, its sources and draw count; ../chromium/program_capture.mjs)}
// Defaults: environmentRotationDeg 90 (matches pbrlab's equirect convention, checked by
// pbrlab.checking.fidelity.check_staging), msaa 0, unpremultiply true for a view spec camera
// (the benchmark's output: colour not premultiplied) and false otherwise (as before);
// iblSampler: the lowered settings below, with a view spec camera also VIEW_SPEC_IBL_SAMPLER.
// Writes OUT.f32 (float32 RGBA, rows top to bottom, linear radiance before tonemap and
// encode; alpha 0 where no surface; colour as the viewer blends it, i.e. premultiplied by
// alpha, unless unpremultiply), OUT.png (8-bit, IEC 61966-2-1 sRGB encode of the clamped
// linear values, for looking at) and OUT.json (size, WebGL renderer, timings).
// Chromium's start-up and the page's server: tools/chromium/launch.mjs.
import { readFileSync } from "node:fs";
import { writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { encode } from "fast-png";
import { rowsTopDown, runPage, runTool } from "../chromium/launch.mjs";
import { capturedPrograms, installProgramCapture } from "../chromium/program_capture.mjs";

const HERE = dirname(fileURLToPath(import.meta.url));
const VIEWER_DIST = join(HERE, "node_modules", "@khronosgroup", "gltf-viewer", "dist");
const PAGE = join(HERE, "page");
// The viewer prefilters its environment on the GPU at load (iblSampler: a 256^2 cube, 2048
// Lambertian and 1024 GGX samples per texel, two 1024^2 BRDF tables of 512 samples), which
// SwiftShader on two shared cores does not finish within minutes. The module is served
// with these constructor settings lowered (each must match the bundle exactly once, so a
// new viewer version fails loudly rather than rendering with other settings). Filtered
// importance sampling (its u_lodBias / mip-level source) keeps the lower counts noise-free
// for smooth environments; the tables are sampled bilinearly.
const IBL_SAMPLER_SETTINGS = [
  ["this.textureSize = 256;", "this.textureSize = 128;"],
  ["this.ggxSampleCount = 1024;", "this.ggxSampleCount = 256;"],
  ["this.lambertianSampleCount = 2048;", "this.lambertianSampleCount = 256;"],
  ["this.sheenSamplCount = 64;", "this.sheenSamplCount = 16;"],
  ["this.lutResolution = 1024;", "this.lutResolution = 128;"],
];
const VIEWER_MODULE = "gltf-viewer.module.js";
const VIEWER_VERSION = JSON.parse(readFileSync(join(HERE, "node_modules", "@khronosgroup", "gltf-viewer", "package.json"), "utf8")).version;
// The viewer's environment turn (renderingParameters.environmentRotation, degrees) at which it
// sees pbrlab's equirect sky (harness/pbrlab/scene/environment.py); the viewer's own default.
const ENVIRONMENT_ROTATION_DEG = 90.0;

// spec.iblSampler: {"textureSize", "ggxSampleCount", "lambertianSampleCount",
// "sheenSamplCount", "lutResolution"} overrides the lowered values (the viewer's own
// defaults: 256, 1024, 2048, 64, 1024).
function iblSettings(overrides = {}) {
  const known = IBL_SAMPLER_SETTINGS.map(([from]) => from.match(/^this\.(\w+) =/)[1]);
  for (const [key, value] of Object.entries(overrides))
    if (!known.includes(key) || !Number.isInteger(value) || value <= 0)
      throw new Error(`spec.iblSampler.${key}: expected one of ${known.join(", ")} with a positive integer`);
  return IBL_SAMPLER_SETTINGS.map(([from, to], i) =>
    [from, overrides[known[i]] === undefined ? to : `this.${known[i]} = ${overrides[known[i]]};`]);
}

// For the fidelity benchmark's view spec: the viewer's own Lambertian sample count. With 256,
// an environment with a small bright sun (/work/fidelity_staging/sunrise.exr, peak 34560)
// leaves a white diffuse sphere 24 % (median) off its irradiance / pi, and 55 % (red mean)
// from +X; with 2048 it is 4 % (the viewer's full defaults: 3 %), at 35 s instead of 10 s a
// render on two shared cores (the full defaults: 150 s). pbrlab.checking.fidelity.check_staging.
const VIEW_SPEC_IBL_SAMPLER = { lambertianSampleCount: 2048 };

function patchedViewer(text, settings) {
  for (const [from, to] of settings) {
    const count = text.split(from).length - 1;
    if (count !== 1) throw new Error(`${VIEWER_MODULE}: expected "${from}" once, found it ${count} times`);
    text = text.replace(from, to);
  }
  return text;
}

// /viewer/* -> the viewer's dist, /page/* -> page/, /fs/ABS -> ABS when under an allowed root
function servedFile(path, allowedRoots) {
  if (path.startsWith("/viewer/")) return join(VIEWER_DIST, path.slice(8));
  if (path.startsWith("/page/")) return join(PAGE, path.slice(6));
  if (path.startsWith("/fs/")) {
    const abs = resolve("/" + path.slice(4));
    if (allowedRoots.some((root) => abs.startsWith(root + "/"))) return abs;
  }
  return null;
}

// The view spec's camera (eye, target, up: glTF coordinates) as the viewer's user camera:
// its camera-to-world matrix, column-major, with the basis of three.js's lookAt and of
// harness/pbrlab/checking/sample_viewer.py camera_spec (x = forward x up, y = x x forward,
// z = -forward), and the field of view in radians.
function cameraFromViewSpec(c) {
  for (const key of ["eye", "target", "up"])
    if (!Array.isArray(c[key]) || c[key].length !== 3) throw new Error(`spec.camera.${key} must be [x, y, z]`);
  for (const key of ["yfov_deg", "znear", "zfar"])
    if (typeof c[key] !== "number" || !(c[key] > 0)) throw new Error(`spec.camera.${key} must be a positive number`);
  const sub = (a, b) => a.map((x, i) => x - b[i]);
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a) => {
    const n = Math.hypot(...a);
    if (!(n > 0)) throw new Error("spec.camera: eye equals target, or up is parallel to the view direction");
    return a.map((x) => x / n);
  };
  const forward = unit(sub(c.target, c.eye));
  const right = unit(cross(forward, c.up));
  const up = cross(right, forward);
  return { cameraToWorld: [...right, 0, ...up, 0, ...forward.map((x) => -x), 0, ...c.eye, 1],
           yfovRad: c.yfov_deg * Math.PI / 180, znear: c.znear, zfar: c.zfar };
}

function unpremultiply(rows) {
  for (let i = 0; i < rows.length; i += 4) {
    const a = rows[i + 3];
    if (a > 0) {
      rows[i] /= a;
      rows[i + 1] /= a;
      rows[i + 2] /= a;
    }
  }
}

function srgb8(linear, width, height) {
  const out = new Uint8Array(width * height * 4);
  for (let i = 0; i < linear.length; i++) {
    const v = Math.min(Math.max(linear[i], 0), 1);
    const e = (i % 4 === 3) ? v : (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055);
    out[i] = Math.round(e * 255);
  }
  return out;
}

async function main(given, outPrefix) {
  const viewSpec = given.camera && given.camera.eye !== undefined;
  const environment = given.environment_hdr ?? given.environment ?? null;
  if (environment && !/\.hdr$/i.test(environment))
    throw new Error(`${environment}: the sample viewer reads Radiance .hdr environments (the view spec's environment_hdr)`);
  const spec = { ...given, environment,
                 camera: viewSpec ? cameraFromViewSpec(given.camera) : given.camera,
                 environmentRotationDeg: given.environmentRotationDeg ?? ENVIRONMENT_ROTATION_DEG,
                 msaa: given.msaa ?? 0 };
  const straight = given.unpremultiply ?? viewSpec;
  const settings = iblSettings(viewSpec ? { ...VIEW_SPEC_IBL_SAMPLER, ...given.iblSampler } : given.iblSampler);
  const t0 = Date.now();
  const roots = [dirname(resolve(spec.gltf))];
  if (spec.environment) roots.push(dirname(resolve(spec.environment)));
  let t1 = t0;
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => servedFile(path, roots),
    transform: (file, body) => (file === join(VIEWER_DIST, VIEWER_MODULE) ? patchedViewer(body.toString("utf8"), settings) : body),
    page: "/page/index.html",
  }, async (page, base) => {
    t1 = Date.now();
    const pageSpec = { ...spec, gltf: `${base}/fs${resolve(spec.gltf)}`,
                       environment: spec.environment ? `${base}/fs${resolve(spec.environment)}` : null };
    if (spec.capturePrograms) await page.evaluate(installProgramCapture);
    const rendered = await page.evaluate((s) => window.renderGltf(s), pageSpec);
    return spec.capturePrograms ? { ...rendered, programs: await page.evaluate(capturedPrograms) } : rendered;
  });
  const t2 = Date.now();
  const [width, height] = spec.size;
  const rows = rowsTopDown(result.pixels, width, height);
  if (straight) unpremultiply(rows);
  await writeFile(`${outPrefix}.f32`, Buffer.from(rows.buffer));
  if (spec.capturePrograms) await writeFile(`${outPrefix}.programs.json`, JSON.stringify(result.programs, null, 1));
  await writeFile(`${outPrefix}.png`, encode({ width, height, data: srgb8(rows, width, height), channels: 4 }));
  await writeFile(`${outPrefix}.json`, JSON.stringify({
    size: [width, height], renderer: result.renderer, version: `gltf-viewer ${VIEWER_VERSION}`,
    webgl_version: result.version, msaa: { ...result.msaa, requested: spec.msaa },
    alpha: straight ? "coverage; colour unpremultiplied" : "coverage; colour premultiplied (as blended)",
    environment_rotation_deg: spec.environmentRotationDeg,
    ibl_sampler: Object.fromEntries(settings.map(([, to]) => to.match(/^this\.(\w+) = (\d+);$/).slice(1, 3))), messages,
    page_seconds: result.seconds,
    seconds: (Date.now() - t0) / 1000,
    seconds_parts: { startup: (t1 - t0) / 1000, render: (t2 - t1) / 1000 },
  }, null, 1));
}

runTool("render.mjs", main);
