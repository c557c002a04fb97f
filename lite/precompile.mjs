// Compile the site's wheels to bytecode with the site's own Pyodide (see lite/precompile.py).
// lite/build.py runs this once at build time, so that no visitor's browser has to.
// Usage: node lite/precompile.mjs PYODIDE_DIR
// rewrites in place every wheel of PYODIDE_DIR and its python_stdlib.zip
import { readdirSync, readFileSync } from "node:fs";
import { dirname, resolve } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const pyodideDir = resolve(process.argv[2]);
const wheels = readdirSync(pyodideDir).filter((f) => f.endsWith(".whl") || f === "python_stdlib.zip")
  .sort().map((f) => `${pyodideDir}/${f}`);
const { loadPyodide } = await import(pathToFileURL(`${pyodideDir}/pyodide.mjs`).href);
// no column tables in the bytecode (the ^^^ under a traceback's line): a third smaller
const pyodide = await loadPyodide({ indexURL: `${pyodideDir}/`, env: { PYTHONNODEBUGRANGES: "1" } });
// what precompile.py's WORKLOAD imports, from the site's own lock (before any wheel is rewritten)
await pyodide.loadPackage(["dhlab", "ipython", "jedi", "ipywidgets", "comm", "micropip"], { messageCallback: () => {} });
// the wheels' folders, seen from inside Pyodide at the same paths
for (const folder of new Set(wheels.map((w) => dirname(w)))) {
  pyodide.FS.mkdirTree(folder);
  pyodide.FS.mount(pyodide.FS.filesystems.NODEFS, { root: folder }, folder);
}
const here = dirname(fileURLToPath(import.meta.url));
pyodide.runPython(readFileSync(`${here}/precompile.py`, "utf8"));
pyodide.globals.set("wheels", pyodide.toPy(wheels));
let report;
try {
  report = pyodide.runPython("import json; json.dumps(precompile(wheels))");
} catch (error) {                 // Python's traceback, not Pyodide's whole source
  console.error(`lite/precompile.py failed:\n${error.message}`);
  process.exit(1);
}
for (const [name, [count, before, after]] of Object.entries(JSON.parse(report))) {
  console.log(`    ${name}: ${count} modules compiled, ${(before / 1e6).toFixed(2)} -> ${(after / 1e6).toFixed(2)} MB`);
}
