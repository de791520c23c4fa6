// Headless Chromium with WebGL2 on SwiftShader, driving one page served from localhost:
// the start-up shared by pbrlab's browser tools (tools/sample_viewer/render.mjs, the Khronos
// glTF Sample Renderer; tools/threejs/render.mjs, the three.js example).
//
//   import { chromium } from "playwright-core";   // the caller's own, pinned in its lock file
//   const { result, messages } = await runPage(chromium, {
//     resolveFile: (path) => absolute file to serve for a URL path, or null (404),
//     transform: (file, bytes) => bytes (optional: a served file's body rewritten),
//     page: "/page/index.html",
//   }, async (page, base) => page.evaluate(...));
//
// The page must set window.pageReady = true once its scripts are loaded. messages: the
// page's console errors and warnings, HTTP errors and uncaught exceptions ("pageerror: ..."),
// in order. Files are served read-only from an ephemeral port on 127.0.0.1; the server and
// the browser are closed when fn returns or throws. Chromium's path is $PBRLAB_CHROMIUM or
// /usr/bin/chromium (Debian's package, installed by scripts/setup.sh). This module imports
// no npm package: playwright-core lives in each tool's own node_modules, so the caller
// passes its browser type.
import { createServer } from "node:http";
import { readFile } from "node:fs/promises";
import { extname } from "node:path";

export const CHROMIUM = process.env.PBRLAB_CHROMIUM || "/usr/bin/chromium";
// WebGL2 without a GPU: ANGLE on SwiftShader (Mesa's EGL is not usable from Chromium here).
export const CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                              "--no-sandbox", "--disable-dev-shm-usage"];
const PAGE_READY_TIMEOUT_MS = 30000;
const TYPES = { ".html": "text/html", ".mjs": "text/javascript", ".js": "text/javascript",
                ".wasm": "application/wasm", ".json": "application/json", ".gltf": "model/gltf+json",
                ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg", ".glsl": "text/plain" };

function serve(resolveFile, transform) {
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
    const file = resolveFile(path);
    try {
      if (file === null) throw new Error("not served");
      const body = transform ? transform(file, await readFile(file)) : await readFile(file);
      response.writeHead(200, { "Content-Type": TYPES[extname(file).toLowerCase()] || "application/octet-stream" });
      response.end(body);
    } catch {
      response.writeHead(404);
      response.end();
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok(server)));
}

export async function runPage(chromium, { resolveFile, transform = null, page: pagePath }, fn) {
  const server = await serve(resolveFile, transform);
  const base = `http://127.0.0.1:${server.address().port}`;
  const messages = [];
  let browser = null;
  try {
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true });
    const page = await browser.newPage();
    page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") messages.push(`${m.type()}: ${m.text()}`); });
    page.on("response", (r) => { if (r.status() >= 400) messages.push(`error: HTTP ${r.status()} for ${r.url()}`); });
    page.on("pageerror", (e) => messages.push(`pageerror: ${e.message}`));
    await page.goto(`${base}${pagePath}`);
    await page.waitForFunction(() => window.pageReady === true, null, { timeout: PAGE_READY_TIMEOUT_MS });
    const result = await fn(page, base);
    return { result, messages };
  } catch (error) {
    // the page's own messages (a module that failed to load, an exception) say why
    if (messages.length) error.message += `\npage messages:\n${messages.join("\n")}`;
    throw error;
  } finally {
    if (browser) await browser.close();
    server.close();
  }
}

// An example page's own view (examples/threejs, examples/babylonjs: a canvas #view and a
// paragraph #status that reads "loading…" until the page has drawn or failed): waits for
// it, writes a PNG of the canvas as shown and returns the status line.
export async function screenshotView(page, pngPath) {
  await page.waitForFunction(() => !document.getElementById("status").textContent.startsWith("loading"), null,
                             { timeout: PAGE_READY_TIMEOUT_MS });
  await page.locator("#view").screenshot({ path: pngPath });
  return page.evaluate(() => document.getElementById("status").textContent);
}

// The float32 RGBA pixels a page read back with readPixels (rows bottom to top), sent as
// base64, as rows top to bottom.
export function rowsTopDown(base64, width, height) {
  const bottomUp = new Float32Array(new Uint8Array(Buffer.from(base64, "base64")).buffer);
  if (bottomUp.length !== width * height * 4) throw new Error(`${bottomUp.length} floats, expected ${width * height * 4}`);
  const rows = new Float32Array(bottomUp.length);
  const stride = width * 4;
  for (let y = 0; y < height; y++) rows.set(bottomUp.subarray((height - 1 - y) * stride, (height - y) * stride), y * stride);
  return rows;
}

// A tool's entry point: `node TOOL SPEC.json OUT` calls main(spec, outPrefix); errors end
// the process with exit 1 and one line naming the tool.
export function runTool(name, main) {
  const [specPath, outPrefix] = process.argv.slice(2);
  if (!specPath || !outPrefix) {
    console.error(`usage: node ${name} SPEC.json OUT`);
    process.exit(2);
  }
  readFile(specPath, "utf8").then((text) => main(JSON.parse(text), outPrefix)).catch((error) => {
    console.error(`${name}: ${error.message || error}`);
    process.exit(1);
  });
}
