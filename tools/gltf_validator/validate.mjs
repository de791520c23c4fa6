// The Khronos glTF Validator (npm gltf-validator) over the files named on the command line:
// one JSON line per file, {"path", "errors", "warnings", "infos", "messages": [...]} (errors
// and warnings only, each "code pointer: message"). External buffers and images are loaded
// from beside the file, so they are validated too. Exit 0 whatever the findings: the caller
// (tests/importers/gltf/test_assets_validate.py) decides what passes.
import { readFile } from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

for (const file of process.argv.slice(2)) {
  const full = path.resolve(file);
  const bytes = new Uint8Array(await readFile(full));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(full),
    maxIssues: 200,
    externalResourceFunction: async (uri) =>
      new Uint8Array(await readFile(path.resolve(path.dirname(full), decodeURIComponent(uri)))),
  });
  const issues = report.issues;
  const messages = issues.messages
    .filter((m) => m.severity <= 1)
    .map((m) => `${["error", "warning"][m.severity]} ${m.code} ${m.pointer ?? ""}: ${m.message}`);
  console.log(JSON.stringify({ path: file, errors: issues.numErrors, warnings: issues.numWarnings,
                               infos: issues.numInfos, messages }));
}
