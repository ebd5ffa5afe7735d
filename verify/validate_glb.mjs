// Validates GLB files with the Khronos glTF validator (npm: gltf-validator).
// Usage: node verify/validate_glb.mjs FILE.glb...  (exit 1 on any error or warning)
// Run by .ci/run on the demo's GLBs; install with
//   npm install --prefix <dir> gltf-validator@2.0.0-dev.3.10
import { createRequire } from 'module';
import { readFileSync } from 'fs';

const require = createRequire(process.env.GLTF_VALIDATOR_DIR
  ? process.env.GLTF_VALIDATOR_DIR + '/'
  : import.meta.url);
const validator = require('gltf-validator');

let failed = false;
for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)));
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages.filter((m) => m.severity <= 1)) {
    console.log(`  [${m.severity === 0 ? 'error' : 'warning'}] ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  }
  if (i.numErrors > 0 || i.numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
