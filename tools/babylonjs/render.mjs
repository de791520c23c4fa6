#!/usr/bin/env node
// Runs the Babylon.js example (examples/babylonjs) in headless Chromium (WebGL2 on SwiftShader)
// and writes what it drew, for tests/examples/test_babylonjs_example.py.
//
//   node render.mjs SPEC.json OUT
//
// SPEC.json, OUT and "show": tools/chromium/example_page.mjs (shared with the other browser
// example); the engine's version is written as "babylon". Chromium's start-up and the page's
// server: tools/chromium/launch.mjs.
import { chromium } from "playwright-core";
import { runTool } from "../chromium/launch.mjs";
import { runExample } from "../chromium/example_page.mjs";

runTool("render.mjs", (spec, outPrefix) => runExample(chromium, { example: "babylonjs", versionKey: "babylon" }, spec, outPrefix));
