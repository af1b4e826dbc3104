// Runs the Khronos glTF-Validator (npm package gltf-validator) over glTF/GLB files, all in this one
// process, and prints one JSON line per file:
//   {"file": PATH, "errors": [{"code": CODE, "pointer": POINTER}, ...], "failed": REASON-or-null}
// "errors" holds the issues of severity 0 (Error); warnings, infos and hints are left out, since
// only errors make a file invalid. Files come from the arguments, or one a line on stdin.
// The package is looked up in $RELT_VALIDATOR_MODULES (a node_modules folder), else in
// build/validator/node_modules. `node validate.mjs --version` prints the validator's version.
import fs from 'node:fs';
import path from 'node:path';
import readline from 'node:readline';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const modules = process.env.RELT_VALIDATOR_MODULES || path.join(root, 'build', 'validator', 'node_modules');
let validator;
try {
  validator = createRequire(path.join(modules, 'index.js'))('gltf-validator');
} catch (e) {
  console.error(`validate.mjs: gltf-validator not found in ${modules} (run scripts/validator/install.sh)`);
  process.exit(3);
}

// External buffers and images are read relative to the file, as relt does. A URI that does not
// resolve to a readable file makes the validator report IO_ERROR, which is what it should do.
function resources(file) {
  return (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) => {
      if (err) reject(err.toString());
      else resolve(new Uint8Array(data));
    });
  });
}

async function validate(file) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    return { file, errors: [{ code: 'IO_ERROR', pointer: '' }], failed: `cannot read: ${e.code}` };
  }
  try {
    const report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0,
      writeTimestamp: false,
      externalResourceFunction: resources(file),
    });
    const errors = report.issues.messages.filter((m) => m.severity === 0)
      .map((m) => ({ code: m.code, pointer: m.pointer || '' }));
    return { file, errors, failed: null };
  } catch (e) {
    // The promise is rejected when the format cannot be detected at all (e.g. an empty file):
    // the validator refuses the file, so it counts as an error.
    return { file, errors: [{ code: 'VALIDATOR_REFUSED', pointer: '' }], failed: String(e).slice(0, 200) };
  }
}

async function main() {
  const args = process.argv.slice(2);
  if (args[0] === '--version') {
    console.log(validator.version());
    return;
  }
  const files = args.length ? args : [];
  if (!args.length) {
    for await (const line of readline.createInterface({ input: process.stdin })) if (line) files.push(line);
  }
  for (const file of files) process.stdout.write(JSON.stringify(await validate(file)) + '\n');
}

main();
