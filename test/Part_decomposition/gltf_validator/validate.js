#!/usr/bin/env node
// Validates each glTF or GLB file given with the Khronos glTF validator; prints the issues of
// each file (errors and warnings; infos with --verbose) and exits with status 1 if any file has an
// error or cannot be read.
//
//   node validate.js [--verbose] FILE...

'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const severities = ['error', 'warning', 'info', 'hint'];

async function validate(file, verbose) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    writeTimestamp: false,
    // resources next to a .gltf file (buffers, images) are validated too
    externalResourceFunction: (uri) => new Promise((resolve, reject) => {
      fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)),
                  (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
    }),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints`);
  for (const m of issues.messages) {
    if (m.severity <= 1 || verbose)
      console.log(`  ${severities[m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
  }
  return issues.numErrors === 0;
}

async function main() {
  const args = process.argv.slice(2);
  const verbose = args.includes('--verbose');
  const files = args.filter((a) => a !== '--verbose');
  if (files.length === 0) {
    console.error('usage: node validate.js [--verbose] FILE...');
    process.exit(2);
  }
  let ok = true;
  for (const file of files) {
    try {
      ok = (await validate(file, verbose)) && ok;
    } catch (e) {
      console.log(`${file}: cannot be validated: ${e}`);
      ok = false;
    }
  }
  process.exit(ok ? 0 : 1);
}

main();
