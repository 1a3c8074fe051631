#!/usr/bin/env node
// Validates .glb files with Khronos' reference glTF validator (npm package gltf-validator,
// installed by `bash voxelfair.sh setup` into ~/.cache/voxelfair/npm, or VOXELFAIR_NPM_DIR).
// Prints one line per file with its error, warning, info and hint counts and every error and
// warning; exits 1 when any file has an error or a warning, 2 when the validator is missing.
//
//   node tools/gltf_validate.js out/3tnk.glb out/robo.glb
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');

const npmDir = process.env.VOXELFAIR_NPM_DIR || path.join(os.homedir(), '.cache', 'voxelfair', 'npm');
let validator;
try {
  validator = require(require.resolve('gltf-validator', {paths: [path.join(npmDir, 'node_modules'), __dirname]}));
} catch (e) {
  console.error(`gltf_validate: gltf-validator not found under ${npmDir} (run: bash voxelfair.sh setup)`);
  process.exit(2);
}

async function main(files) {
  let bad = 0;
  for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: file,
      maxIssues: 100,
      externalResourceFunction: () => Promise.reject(new Error('a .glb must be self-contained')),
    });
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages)
      if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (i.numErrors > 0 || i.numWarnings > 0) bad += 1;
  }
  process.exit(bad > 0 ? 1 : 0);
}

main(process.argv.slice(2)).catch((e) => {
  console.error(`gltf_validate: ${e}`);
  process.exit(1);
});
