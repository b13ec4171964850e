// Validates glTF files with the Khronos glTF-Validator: every file must have zero errors and
// zero warnings. Usage: node validate.mjs FILE.glb|FILE.gltf ...
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

let failed = 0;
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: file,
    maxIssues: 50,
    externalResourceFunction: (uri) =>
      readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const { numErrors, numWarnings, messages } = report.issues;
  const ok = numErrors === 0 && numWarnings === 0;
  if (!ok) failed++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${file}: ${numErrors} errors, ${numWarnings} warnings, ` +
              `${report.info ? report.info.totalVertexCount + ' vertices' : ''}`);
  for (const m of messages.filter((m) => m.severity <= 1).slice(0, 10))
    console.log(`     ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
}
process.exit(failed ? 1 : 0);
