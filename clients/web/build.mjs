// Builds the dashboard into OUT: semnav-dashboard.js (the Node proxy, dependencies bundled),
// static/ (page bundle, HTML, CSS) and the tests dashboard_e2e.js and stack_e2e.js (Playwright) and proxy_test.js. The page's proto
// types are generated first (src/generated/protos.ts). Usage: node build.mjs [--out DIR]
import * as fs from "node:fs";
import * as path from "node:path";
import { fileURLToPath } from "node:url";
import { createRequire } from "node:module";
import { generate } from "./gen_types.mjs";

const require = createRequire(import.meta.url);
const esbuild = require("esbuild");
const here = path.dirname(fileURLToPath(import.meta.url));
const protoDir = path.resolve(here, "../../protos");
const outFlag = process.argv.indexOf("--out");
const out = path.resolve(outFlag > 0 ? process.argv[outFlag + 1] : path.join(here, "../../build/release/web"));

const generated = path.join(here, "src/generated/protos.ts");
fs.mkdirSync(path.dirname(generated), { recursive: true });
const types = generate(protoDir);
if (!fs.existsSync(generated) || fs.readFileSync(generated, "utf8") !== types) fs.writeFileSync(generated, types);

const node = { bundle: true, platform: "node", target: "node20", format: "cjs", logLevel: "warning", sourcemap: true };
await Promise.all([
  esbuild.build({
    ...node,
    entryPoints: [path.join(here, "src/server/main.ts")],
    outfile: path.join(out, "semnav-dashboard.js"),
    define: { DEFAULT_PROTO_DIR: JSON.stringify(protoDir) },
  }),
  esbuild.build({
    ...node,
    entryPoints: [path.join(here, "src/test/dashboard_e2e.ts"), path.join(here, "src/test/proxy_test.ts"),
                  path.join(here, "src/test/stack_e2e.ts")],
    outdir: out,
    external: ["playwright-core"],
    define: { DEFAULT_PROTO_DIR: JSON.stringify(protoDir), NODE_MODULES_DIR: JSON.stringify(path.resolve(here, "../../node_modules")) },
  }),
  esbuild.build({
    bundle: true, platform: "browser", target: "chrome110", format: "iife", logLevel: "warning", sourcemap: true,
    entryPoints: [path.join(here, "src/page/main.ts")],
    outfile: path.join(out, "static/app.js"),
  }),
]);
for (const file of ["index.html", "style.css"]) {
  fs.copyFileSync(path.join(here, "src/page", file), path.join(out, "static", file));
}
