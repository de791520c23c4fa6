#!/usr/bin/env node
// Babylon.js's own shader preprocessor, run on one fragment shader outside the browser: what
// a ShaderMaterial hands to WebGL2 after Babylon has evaluated the shader's #if / #ifdef /
// #define lines itself (Engines/Processors/shaderProcessor.js, the options Effect passes on a
// WebGL2 engine). tests/library/test_engine_preprocessors.py compares the result with
// glslang's preprocessing of the same file.
//
//   node preprocess.mjs IN.glsl OUT.glsl [NAME=VALUE ...]
//
// NAME=VALUE: a define, as ShaderMaterial's `defines` option passes it ("#define NAME VALUE").
import { readFile, writeFile } from "node:fs/promises";
import { Process } from "@babylonjs/core/Engines/Processors/shaderProcessor.js";
import { WebGL2ShaderProcessor } from "@babylonjs/core/Engines/WebGL/webGL2ShaderProcessors.js";

const [input, output, ...defines] = process.argv.slice(2);
if (!input || !output) {
  console.error("usage: node preprocess.mjs IN.glsl OUT.glsl [NAME=VALUE ...]");
  process.exit(2);
}
const options = {
  defines: defines.map((d) => `#define ${d.replace("=", " ")}`),
  indexParameters: {},
  isFragment: true,
  shouldUseHighPrecisionShader: true,
  processor: new WebGL2ShaderProcessor(),
  supportsUniformBuffers: true,
  shadersRepository: "",
  includesShadersStore: {},
  version: "200",             // a WebGL2 engine's (engine.version 2, times 100)
  platformName: "WEBGL2",
  processingContext: null,
};
const source = await readFile(input, "utf8");
Process(source, options, (code) => writeFile(output, code).catch((e) => {
  console.error(`preprocess.mjs: ${e.message}`);
  process.exit(1);
}), undefined);
