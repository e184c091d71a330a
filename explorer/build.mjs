// Bundles the explorer (esbuild) into build/explorer/ with the page, its CSS and the WebAssembly
// core (build/wasm/selfalign_core.js + .wasm, from scripts/build-wasm.sh). Nothing is fetched
// at run time: uplot and plotly.js-dist-min are bundled from node_modules (package-lock.json).
//   node explorer/build.mjs [outdir]
import { build } from 'esbuild';
import { copyFileSync, mkdirSync, existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '..');
const out = resolve(process.argv[2] ?? join(root, 'build', 'explorer'));
const wasm = join(root, 'build', 'wasm');
for (const f of ['selfalign_core.js', 'selfalign_core.wasm'])
  if (!existsSync(join(wasm, f))) {
    console.error(`explorer: ${join(wasm, f)} is missing: run scripts/build-wasm.sh first`);
    process.exit(2);
  }
mkdirSync(out, { recursive: true });
await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  format: 'iife',
  target: ['chrome100', 'firefox100', 'safari15'],
  minify: true,
  sourcemap: true,
  outdir: out,
  loader: { '.toml': 'text' },  // examples/planar.toml, the planar view's starting config
  logLevel: 'warning',
});
copyFileSync(join(here, 'index.html'), join(out, 'index.html'));
for (const f of ['selfalign_core.js', 'selfalign_core.wasm']) copyFileSync(join(wasm, f), join(out, f));
console.log(`explorer: built ${out}`);
