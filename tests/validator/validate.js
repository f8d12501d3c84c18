// Validates glTF files with the Khronos glTF-Validator and prints one line per file:
//   FILE: E errors, W warnings[: first codes]
// then every warning code with its count. Exit status 1 if any file has an error.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const dir = path.dirname(file);
  return validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(dir, decodeURIComponent(uri)), (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
      }),
  });
}

(async () => {
  let failed = false;
  const warningCodes = new Map();
  for (const file of process.argv.slice(2)) {
    const report = await validate(file);
    const { numErrors, numWarnings, messages } = report.issues;
    const errors = messages.filter((m) => m.severity === 0).map((m) => `${m.code} ${m.pointer || ''}`.trim());
    for (const m of messages.filter((m) => m.severity === 1)) warningCodes.set(m.code, (warningCodes.get(m.code) || 0) + 1);
    console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings${errors.length ? ': ' + errors.slice(0, 5).join('; ') : ''}`);
    if (numErrors > 0) failed = true;
  }
  for (const [code, count] of warningCodes) console.log(`warning ${code}: ${count} file(s)`);
  process.exit(failed ? 1 : 0);
})().catch((e) => {
  console.error(`validate.js: ${e}`);
  process.exit(2);
});
