// viewer/build.mjs
// Bundles src/viewer.js with three.js into one minified script, the one `hmira view` inlines
// into every page:  node build.mjs [OUT.js]   (default dist/hmira-viewer.js)
import { build } from 'esbuild';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const out = resolve(process.argv[2] ?? resolve(here, 'dist/hmira-viewer.js'));
await build({
    entryPoints: [resolve(here, 'src/viewer.js')],
    bundle: true,
    minify: true,
    format: 'iife',
    target: 'es2020',
    legalComments: 'inline',  // three.js's MIT notice stays in every page
    charset: 'utf8',
    outfile: out,
    logLevel: 'warning',
});
console.log(`viewer: bundle written to ${out}`);
