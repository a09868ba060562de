// Validates glTF files with the Khronos glTF validator (npm package gltf-validator).
// Usage: node validate.js VALIDATOR_FOLDER FILE...  Prints one line per file with the number of
// errors and warnings and every error; exits 1 when any file has an error.
const fs = require('fs');
const path = require('path');
const validator = require(path.join(process.argv[2], 'node_modules', 'gltf-validator'));

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    // A .gltf refers to its .bin by a name relative to itself.
    externalResourceFunction: (uri) => new Promise((resolve, reject) => {
      fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)),
                  (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)));
    }),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos`);
  for (const m of issues.messages)
    if (m.severity === 0) console.log(`  error ${m.code} at ${m.pointer}: ${m.message}`);
  return issues.numErrors;
}

(async () => {
  let errors = 0;
  for (const file of process.argv.slice(3)) errors += await validate(file);
  process.exit(errors > 0 ? 1 : 0);
})().catch((e) => {
  console.log(`validator failed: ${e}`);
  process.exit(2);
});
