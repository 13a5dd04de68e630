// Fails, naming each file and line, where a line of the repository's JavaScript, CSS or HTML (the
// dashboard, the browser tests, the benchmarks) is longer than 120 columns, the project's style
// rule (clang-format holds C++ to it). Columns are Unicode code points, so that "γ/k_n" counts 5.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const kMaxColumns = 120;
const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const files = execFileSync('git', ['ls-files', '*.js', '*.mjs', '*.css', '*.html'], { cwd: root, encoding: 'utf8' })
  .split('\n').filter(Boolean);
const long = [];
for (const file of files) {
  readFileSync(path.join(root, file), 'utf8').split('\n').forEach((line, index) => {
    const columns = [...line].length;
    if (columns > kMaxColumns) long.push(`${file}:${index + 1}: ${columns} columns`);
  });
}
if (long.length > 0) {
  console.error(`${long.length} lines over ${kMaxColumns} columns:\n${long.join('\n')}`);
  process.exit(1);
}
console.log(`${files.length} files within ${kMaxColumns} columns`);
