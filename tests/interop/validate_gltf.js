// Validates glTF/GLB files with the Khronos glTF-Validator (npm gltf-validator).
//   node validate_gltf.js VALIDATOR_DIR FILE...
// Prints each file's issues; exits 1 when any file has an error or a warning
// (infos and hints are printed, not counted), 2 when the validator is missing.
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, ...files] = process.argv.slice(2);
let validator;
try {
  validator = require(path.resolve(validatorDir));
} catch (e) {
  console.error(`glTF-Validator not found in ${validatorDir}: run packaging/install-test-tools.sh`);
  process.exit(2);  // nothing was printed to stdout yet
}

function loadResource(file) {
  return (uri) => fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)));
}

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    writeTimestamp: false,
    externalResourceFunction: loadResource(file),
  });
  const issues = report.issues;
  const names = ['error', 'warning', 'info', 'hint'];
  const shownPerCode = 5;  // a broken accessor repeats one message per element
  const seen = new Map();
  for (const message of issues.messages) {
    const count = (seen.get(message.code) || 0) + 1;
    seen.set(message.code, count);
    if (count <= shownPerCode)
      console.log(`${file}: ${names[message.severity]} ${message.code} at ${message.pointer || '-'}: ${message.message}`);
  }
  for (const [code, count] of seen)
    if (count > shownPerCode) console.log(`${file}: ... ${count} ${code} in all`);
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints (glTF-Validator ${validator.version()})`);
  return issues.numErrors + issues.numWarnings === 0;
}

(async () => {
  if (files.length === 0) {
    console.error('usage: node validate_gltf.js VALIDATOR_DIR FILE...');
    process.exit(2);
  }
  let clean = true;
  for (const file of files) clean = (await validate(file)) && clean;
  process.exitCode = clean ? 0 : 1;  // not process.exit(): that would cut a piped stdout short
})().catch((e) => {
  console.error(String(e));
  process.exitCode = 1;
});
