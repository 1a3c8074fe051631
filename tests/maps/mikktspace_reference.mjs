// Compares our MikkTSpace tangents (written by maps_tangent_dump) with the reference
// implementation's: the npm package `mikktspace`, a WebAssembly build of Mikkelsen's code.
//   node mikktspace_reference.mjs NODE_MODULES_DIR FILE.bin...
// Fails unless every corner's tangent (xyz and sign) is within 1e-3 of the reference's.
import { createRequire } from 'module';
import fs from 'fs';
const require = createRequire(import.meta.url);
const [modules, ...files] = process.argv.slice(2);
const { generateTangents } = require(`${modules}/mikktspace`);
let failed = false;
for (const file of files) {
  const bytes = fs.readFileSync(file);
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const n = new Uint32Array(buffer, 0, 1)[0];
  let offset = 4;
  const take = (k) => { const a = new Float32Array(buffer, offset, n * k); offset += n * k * 4; return a; };
  const position = take(3), normal = take(3), uv = take(2), ours = take(4);
  const reference = generateTangents(position, normal, uv);
  let worst = 0, bad = 0;
  for (let c = 0; c < n; ++c) {
    let d = 0;
    for (let k = 0; k < 4; ++k) d = Math.max(d, Math.abs(ours[4 * c + k] - reference[4 * c + k]));
    if (d > 1e-3) ++bad;
    worst = Math.max(worst, d);
  }
  console.log(`${file}: ${n / 3} triangles, largest difference ${worst.toExponential(2)}, ${bad} corners beyond 1e-3`);
  if (bad > 0) failed = true;
}
process.exit(failed ? 1 : 0);
