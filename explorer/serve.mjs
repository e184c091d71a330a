// A static file server on the loopback interface for build/explorer/ (the page has no server
// side: this only hands out its files, with the .wasm MIME type that streaming compilation needs).
//   node explorer/serve.mjs [dir] [port]     (port 0: any free port; prints the URL)
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize, resolve, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.wasm': 'application/wasm', '.map': 'application/json',
  '.png': 'image/png',
};

// Serves `dir` on 127.0.0.1:`port`; resolves to the server once listening.
export function serve(dir, port = 0) {
  const root = resolve(dir);
  const server = createServer(async (req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    const file = normalize(join(root, path === '/' ? 'index.html' : path));
    if (!file.startsWith(root)) { res.writeHead(403).end(); return; }
    try {
      const body = await readFile(file);
      res.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  return new Promise((ok, fail) => {
    server.once('error', fail);
    server.listen(port, '127.0.0.1', () => ok(server));
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const here = dirname(fileURLToPath(import.meta.url));
  const dir = process.argv[2] ?? join(here, '..', 'build', 'explorer');
  const port = Number(process.argv[3] ?? 8765);
  const server = await serve(dir, port).catch((e) => {
    console.error(`invalid port = ${port}: ${e.code === 'EADDRINUSE' ? 'in use; give another' : e.message}`);
    process.exit(2);
  });
  console.log(`explorer: http://127.0.0.1:${server.address().port}/  (Ctrl-C stops)`);
}
