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
// Files are served read-only from an ephemeral localhost port; Chromium's path is
// $PBRLAB_CHROMIUM or /usr/bin/chromium.
import { createServer } from "node:http";
import { readFile, writeFile } from "node:fs/promises";
import { dirname, extname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { encode } from "fast-png";

const HERE = dirname(fileURLToPath(import.meta.url));
const VIEWER_DIST = join(HERE, "node_modules", "@khronosgroup", "gltf-viewer", "dist");
const PAGE = join(HERE, "page");
const CHROMIUM = process.env.PBRLAB_CHROMIUM || "/usr/bin/chromium";
// WebGL2 without a GPU: ANGLE on SwiftShader (Mesa's EGL is not usable from Chromium here).
const CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                       "--no-sandbox", "--disable-dev-shm-usage"];
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

const TYPES = { ".html": "text/html", ".mjs": "text/javascript", ".js": "text/javascript",
                ".wasm": "application/wasm", ".json": "application/json", ".gltf": "model/gltf+json",
                ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg" };

function serve(allowedRoots) {
  // /viewer/* -> the viewer's dist, /page/* -> page/, /fs/ABS -> ABS when under an allowed root
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
    let file = null;
    if (path.startsWith("/viewer/")) file = join(VIEWER_DIST, path.slice(8));
    else if (path.startsWith("/page/")) file = join(PAGE, path.slice(6));
    else if (path.startsWith("/fs/")) {
      const abs = resolve("/" + path.slice(4));
      if (allowedRoots.some((root) => abs.startsWith(root + "/"))) file = abs;
    }
    try {
      if (file === null) throw new Error("not served");
      let body = await readFile(file);
      if (file === join(VIEWER_DIST, VIEWER_MODULE)) body = patchedViewer(body.toString("utf8"));
      response.writeHead(200, { "Content-Type": TYPES[extname(file).toLowerCase()] || "application/octet-stream" });
      response.end(body);
    } catch {
      response.writeHead(404);
      response.end();
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok(server)));
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

async function main() {
  const [specPath, outPrefix] = process.argv.slice(2);
  if (!specPath || !outPrefix) {
    console.error("usage: node render.mjs SPEC.json OUT");
    process.exit(2);
  }
  const t0 = Date.now();
  const spec = JSON.parse(await readFile(specPath, "utf8"));
  const roots = [dirname(resolve(spec.gltf))];
  if (spec.environment) roots.push(dirname(resolve(spec.environment)));
  const server = await serve(roots);
  const base = `http://127.0.0.1:${server.address().port}`;
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true });
  const messages = [];
  try {
    const page = await browser.newPage();
    page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") messages.push(`${m.type()}: ${m.text()}`); });
    page.on("response", (r) => { if (r.status() >= 400) messages.push(`error: HTTP ${r.status()} for ${r.url()}`); });
    page.on("pageerror", (e) => messages.push(`pageerror: ${e.message}`));
    await page.goto(`${base}/page/index.html`);
    await page.waitForFunction(() => window.pageReady === true, null, { timeout: 30000 });
    const t1 = Date.now();
    const pageSpec = { ...spec, gltf: `${base}/fs${resolve(spec.gltf)}`,
                       environment: spec.environment ? `${base}/fs${resolve(spec.environment)}` : null };
    const result = await page.evaluate((s) => window.renderGltf(s), pageSpec);
    const t2 = Date.now();
    const [width, height] = spec.size;
    const bottomUp = new Float32Array(new Uint8Array(Buffer.from(result.pixels, "base64")).buffer);
    const rows = new Float32Array(bottomUp.length);
    const stride = width * 4;
    for (let y = 0; y < height; y++) rows.set(bottomUp.subarray((height - 1 - y) * stride, (height - y) * stride), y * stride);
    await writeFile(`${outPrefix}.f32`, Buffer.from(rows.buffer));
    await writeFile(`${outPrefix}.png`, encode({ width, height, data: srgb8(rows, width, height), channels: 4 }));
    await writeFile(`${outPrefix}.json`, JSON.stringify({
      size: [width, height], renderer: result.renderer, version: result.version, messages,
      page_seconds: result.seconds,
      seconds: { startup: (t1 - t0) / 1000, render: (t2 - t1) / 1000, total: (Date.now() - t0) / 1000 },
    }, null, 1));
  } finally {
    await browser.close();
    server.close();
  }
}

main().catch((error) => {
  console.error(`render.mjs: ${error.message || error}`);
  process.exit(1);
});
