// The Khronos glTF validator (npm gltf-validator) over what snow writes and
// ships: snow_run --export of the built-in village, the .glb of the cover
// test scene, and every assets/scenes/*.gltf. Fails on any error; prints
// warnings. Exit 77 (ctest: skipped), with the reason, when npm cannot
// provide the validator.
//
// usage: node validate_gltf.mjs NPM_PREFIX WORK_DIR SNOW_RUN EXPORT_SAMPLE SCENES_DIR
import { spawnSync } from "node:child_process";
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";

const [npmPrefix, workDir, snowRun, exportSample, scenesDir] = process.argv.slice(2);
if (!scenesDir) {
    console.error("usage: node validate_gltf.mjs NPM_PREFIX WORK_DIR SNOW_RUN EXPORT_SAMPLE SCENES_DIR");
    process.exit(2);
}

function loadValidator() {
    const require = createRequire(path.join(path.resolve(npmPrefix), "package.json"));
    try {
        return require("gltf-validator");
    } catch {
        fs.mkdirSync(npmPrefix, { recursive: true });
        const npm = spawnSync("npm", ["install", "--prefix", npmPrefix, "--no-audit", "--no-fund",
                                      "--loglevel=error", "gltf-validator"], { encoding: "utf8" });
        if (npm.error || npm.status !== 0) {
            const why = npm.error ? npm.error.message : (npm.stderr || "").trim().split("\n").slice(-3).join(" | ");
            console.log(`SKIPPED: npm could not install gltf-validator into ${npmPrefix}: ${why}`);
            process.exit(77);
        }
        return require("gltf-validator");
    }
}

function run(cmd, args) {
    const r = spawnSync(cmd, args, { encoding: "utf8" });
    if (r.error || r.status !== 0) {
        console.error(`FAILED: ${cmd} ${args.join(" ")}: ${r.error ? r.error.message : r.stderr}`);
        process.exit(1);
    }
}

const validator = loadValidator();
console.log(`gltf-validator ${validator.version()}`);
fs.mkdirSync(workDir, { recursive: true });
const villageGlb = path.join(workDir, "village.glb");
const coverGlb = path.join(workDir, "cover.glb");
run(snowRun, ["--ticks", "300", "--export", villageGlb]);
run(exportSample, [coverGlb]);

// Exports must hold geometry; shipped scenes only have to be valid.
const files = [{ file: villageGlb, exported: true }, { file: coverGlb, exported: true }];
for (const name of fs.readdirSync(scenesDir).sort()) {
    if (name.endsWith(".gltf") || name.endsWith(".glb")) {
        files.push({ file: path.join(scenesDir, name), exported: false });
    }
}

const severities = ["error", "warning", "info", "hint"];
let failed = 0;
for (const { file, exported } of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)),
                            (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
            }),
    });
    const issues = report.issues;
    for (const m of issues.messages) {
        if (m.severity <= 1) {
            console.log(`  ${severities[m.severity]} ${m.code} at ${m.pointer ?? "-"}: ${m.message}`);
        }
    }
    const vertices = report.info ? report.info.totalVertexCount : 0;
    const empty = exported && !(vertices > 0);
    const ok = issues.numErrors === 0 && !empty;
    failed += ok ? 0 : 1;
    console.log(`${ok ? "ok  " : "FAIL"} ${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints, ${vertices} vertices` +
                (empty ? " (an export without geometry)" : ""));
}
console.log(`${files.length - failed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
