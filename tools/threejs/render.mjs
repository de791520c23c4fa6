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
// Files are served read-only from an ephemeral localhost port; Chromium's path is
// $PBRLAB_CHROMIUM or /usr/bin/chromium.
import { createServer } from "node:http";
import { readFile, writeFile } from "node:fs/promises";
import { dirname, extname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const HERE = dirname(fileURLToPath(import.meta.url));
const REPO = resolve(HERE, "..", "..");
const CHROMIUM = process.env.PBRLAB_CHROMIUM || "/usr/bin/chromium";
// WebGL2 without a GPU: ANGLE on SwiftShader (as tools/sample_viewer/render.mjs).
const CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                       "--no-sandbox", "--disable-dev-shm-usage"];
const TYPES = { ".html": "text/html", ".mjs": "text/javascript", ".js": "text/javascript",
                ".json": "application/json", ".glsl": "text/plain", ".exr": "application/octet-stream" };

function serve(allowedFiles) {
  // /examples/threejs/* and /tools/threejs/node_modules/* from the checkout; /fs/ABS: the spec's files
  const roots = [join(REPO, "examples", "threejs"), join(HERE, "node_modules")];
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
    let file = null;
    if (path.startsWith("/fs/")) {
      const abs = resolve("/" + path.slice(4));
      if (allowedFiles.includes(abs)) file = abs;
    } else {
      const abs = resolve(join(REPO, path));
      if (roots.some((root) => abs.startsWith(root + "/"))) file = abs;
    }
    try {
      if (file === null) throw new Error("not served");
      const body = await readFile(file);
      response.writeHead(200, { "Content-Type": TYPES[extname(file).toLowerCase()] || "application/octet-stream" });
      response.end(body);
    } catch {
      response.writeHead(404);
      response.end();
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok(server)));
}

async function main() {
  const [specPath, outPrefix] = process.argv.slice(2);
  if (!specPath || !outPrefix) {
    console.error("usage: node render.mjs SPEC.json OUT");
    process.exit(2);
  }
  const spec = JSON.parse(await readFile(specPath, "utf8"));
  const files = ["scene", "library", "dfg"].map((key) => resolve(spec[key]));
  const server = await serve(files);
  const base = `http://127.0.0.1:${server.address().port}`;
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true });
  const messages = [];
  try {
    const page = await browser.newPage();
    page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") messages.push(`${m.type()}: ${m.text()}`); });
    page.on("response", (r) => { if (r.status() >= 400) messages.push(`error: HTTP ${r.status()} for ${r.url()}`); });
    page.on("pageerror", (e) => messages.push(`pageerror: ${e.message}`));
    await page.goto(`${base}/examples/threejs/index.html`);
    await page.waitForFunction(() => window.pageReady === true, null, { timeout: 30000 });
    const urls = { scene: `${base}/fs${files[0]}`, library: `${base}/fs${files[1]}`, dfg: `${base}/fs${files[2]}` };
    const result = await page.evaluate(async (u) => {
      const r = await window.renderScene(u);
      const bytes = new Uint8Array(r.pixels.buffer);
      let binary = "";
      for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return { width: r.width, height: r.height, renderer: r.renderer, three: r.three, pixels: btoa(binary) };
    }, urls);
    const { width, height } = result;
    const bottomUp = new Float32Array(new Uint8Array(Buffer.from(result.pixels, "base64")).buffer);
    const rows = new Float32Array(bottomUp.length);
    const stride = width * 4;
    for (let y = 0; y < height; y++) rows.set(bottomUp.subarray((height - 1 - y) * stride, (height - y) * stride), y * stride);
    await writeFile(`${outPrefix}.f32`, Buffer.from(rows.buffer));
    await writeFile(`${outPrefix}.json`, JSON.stringify({ size: [width, height], renderer: result.renderer,
                                                          three: result.three, messages }, null, 1));
  } finally {
    await browser.close();
    server.close();
  }
}

main().catch((error) => {
  console.error(`render.mjs: ${error.message || error}`);
  process.exit(1);
});
