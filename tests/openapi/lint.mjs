// Lints schemas/openapi.json with Redocly CLI (this folder's package.json, installed by
// scripts/setup.sh from the lockfile) against its recommended rules (redocly.yaml), so that client
// generators and API portals take the description as it is. Fails on any error or warning, and
// lists them. Run by CTest ("openapi: Redocly recommended rules"); by hand: node tests/openapi/lint.mjs
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..');
const redocly = join(here, 'node_modules', '@redocly', 'cli', 'bin', 'cli.js');
if (!existsSync(redocly)) {
  console.error(`no Redocly CLI at ${redocly}: run scripts/setup.sh (npm ci in tests/openapi)`);
  process.exit(1);
}
const run = spawnSync(process.execPath, [redocly, 'lint', '--config', join(here, 'redocly.yaml'), '--format', 'json',
  join(root, 'schemas', 'openapi.json')], {
  encoding: 'utf8',
  maxBuffer: 64 << 20,
  timeout: 120_000,
  // No usage report to Redocly and no update check: the test reads nothing but the file.
  env: { ...process.env, REDOCLY_TELEMETRY: 'off', REDOCLY_SUPPRESS_UPDATE_NOTICE: 'true' },
});
let report;
try {
  report = JSON.parse(run.stdout);
} catch {
  console.error(`Redocly CLI gave no report (exit ${run.status}):\n${run.stderr}`);
  process.exit(1);
}
for (const problem of report.problems) {
  const where = problem.location.map((l) => `${l.source.ref}${l.pointer}`).join(', ');
  console.log(`${problem.severity} ${problem.ruleId}: ${problem.message} (${where})`);
}
const { errors, warnings } = report.totals;
console.log(`Redocly CLI ${report.version}, recommended rules: ${errors} errors, ${warnings} warnings`);
process.exit(errors === 0 && warnings === 0 ? 0 : 1);
