import fs from 'fs';
import * as W from 'web-ifc';
const api = new W.IfcAPI();
await api.Init();
api.SetLogLevel(W.LogLevel.LOG_LEVEL_ERROR);
const m = api.OpenModel(new Uint8Array(fs.readFileSync(process.argv[2])));
let n = 0;
api.StreamAllMeshes(m, (mesh) => { n++; });
console.log('meshes', n);
