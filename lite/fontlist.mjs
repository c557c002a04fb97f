// Matplotlib's font list, as Pyodide's matplotlib builds it on first import (a few seconds, and a
// "Matplotlib is building the font cache" warning under the first cell that imports it).
// lite/build.py runs this once at build time and ships the file, so that no kernel has to.
// Usage: node lite/fontlist.mjs PYODIDE_DIR OUTPUT_JSON
import { writeFileSync } from "node:fs";
import { resolve } from "node:path";
import { pathToFileURL } from "node:url";

const [pyodideDir, output] = process.argv.slice(2).map((p) => resolve(p));
const { loadPyodide } = await import(pathToFileURL(`${pyodideDir}/pyodide.mjs`).href);
const pyodide = await loadPyodide({ indexURL: `${pyodideDir}/` });
await pyodide.loadPackage(["matplotlib"], { messageCallback: () => {} });
const text = pyodide.runPython(`
import pathlib, matplotlib.font_manager as fm
# Pyodide's matplotlib keeps its font list beside font_manager.py
path = pathlib.Path(fm.__file__).with_name("fontlist.json")
fm._load_fontmanager(try_read_cache=False)
path.read_text()
`);
writeFileSync(output, text);
