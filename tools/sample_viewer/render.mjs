#!/usr/bin/env node
// Renders one glTF file with the Khronos glTF Sample Renderer (npm @khronosgroup/gltf-viewer)
// in headless Chromium (WebGL2 on SwiftShader), pbrlab's second, independent glTF renderer.
//
//   node render.mjs SPEC.json OUT
//
// SPEC.json: {"gltf": "/abs/model.gltf", "size": [w, h],
//             "camera": {"cameraToWorld": [16 numbers, column-major], "yfovRad": r,
//                        "znear": n, "zfar": f}  or  {"index": glTF camera index},
//             "environment": "/abs/sky.hdr" or null (punctual lights only),
//             "environmentIntensity": 1, "environmentRotationDeg": 90}
// Writes OUT.f32 (float32 RGBA, rows top to bottom, linear radiance before tonemap and
// encode; alpha 0 where no surface), OUT.png (8-bit, IEC 61966-2-1 sRGB encode of the
// clamped linear values, for looking at) and OUT.json (size, WebGL renderer, timings).
// Chromium's start-up and the page's server: tools/chromium/launch.mjs.
import { writeFile } from "node:fs/promises";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { encode } from "fast-png";
import { rowsTopDown, runPage, runTool } from "../chromium/launch.mjs";

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

function patchedViewer(text) {
  for (const [from, to] of IBL_SAMPLER_SETTINGS) {
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

function srgb8(linear, width, height) {
  const out = new Uint8Array(width * height * 4);
  for (let i = 0; i < linear.length; i++) {
    const v = Math.min(Math.max(linear[i], 0), 1);
    const e = (i % 4 === 3) ? v : (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055);
    out[i] = Math.round(e * 255);
  }
  return out;
}

async function main(spec, outPrefix) {
  const t0 = Date.now();
  const roots = [dirname(resolve(spec.gltf))];
  if (spec.environment) roots.push(dirname(resolve(spec.environment)));
  let t1 = t0;
  const { result, messages } = await runPage(chromium, {
    resolveFile: (path) => servedFile(path, roots),
    transform: (file, body) => (file === join(VIEWER_DIST, VIEWER_MODULE) ? patchedViewer(body.toString("utf8")) : body),
    page: "/page/index.html",
  }, async (page, base) => {
    t1 = Date.now();
    const pageSpec = { ...spec, gltf: `${base}/fs${resolve(spec.gltf)}`,
                       environment: spec.environment ? `${base}/fs${resolve(spec.environment)}` : null };
    return page.evaluate((s) => window.renderGltf(s), pageSpec);
  });
  const t2 = Date.now();
  const [width, height] = spec.size;
  const rows = rowsTopDown(result.pixels, width, height);
  await writeFile(`${outPrefix}.f32`, Buffer.from(rows.buffer));
  await writeFile(`${outPrefix}.png`, encode({ width, height, data: srgb8(rows, width, height), channels: 4 }));
  await writeFile(`${outPrefix}.json`, JSON.stringify({
    size: [width, height], renderer: result.renderer, version: result.version, messages,
    page_seconds: result.seconds,
    seconds: { startup: (t1 - t0) / 1000, render: (t2 - t1) / 1000, total: (Date.now() - t0) / 1000 },
  }, null, 1));
}

runTool("render.mjs", main);
