#!/usr/bin/env node
// Runs the three.js example (examples/threejs) in headless Chromium (WebGL2 on SwiftShader)
// and writes what it drew, for tests/examples/test_threejs_example.py.
//
//   node render.mjs SPEC.json OUT
//
// SPEC.json, OUT and "show": tools/chromium/example_page.mjs (shared with the other browser
// example); the engine's version is written as "three". Chromium's start-up and the page's
// server: tools/chromium/launch.mjs.
import { chromium } from "playwright-core";
import { runTool } from "../chromium/launch.mjs";
import { runExample } from "../chromium/example_page.mjs";

runTool("render.mjs", (spec, outPrefix) => runExample(chromium, { example: "threejs", versionKey: "three" }, spec, outPrefix));
