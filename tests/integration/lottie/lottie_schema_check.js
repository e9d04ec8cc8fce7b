// Test tool: validates Lottie files against the Lottie Animation Community's JSON schema
// (lottie-spec, with ajv's draft 2020-12 validator), and reads .lottie archives.
//   node lottie_schema_check.js NODE_MODULES FILE.json|FILE.lottie...
// A .lottie is opened with a zip reader of its own (central directory, stored or deflated
// entries: node's zlib) and must hold manifest.json naming animations that are in
// animations/ID.json; each animation is validated. Prints "FILE: valid" per file, or one line
// per schema error; exit 1 on any error, 2 on a usage error. Schema warnings (unknown
// properties, which the spec allows) are not errors.
'use strict';
const fs = require('fs');
const path = require('path');
const zlib = require('zlib');

function unzip(buf) {
  const files = {};
  let eocd = buf.length - 22;
  while (eocd >= 0 && buf.readUInt32LE(eocd) !== 0x06054b50) --eocd;
  if (eocd < 0) throw new Error('no end of central directory');
  const count = buf.readUInt16LE(eocd + 10);
  let at = buf.readUInt32LE(eocd + 16);
  for (let i = 0; i < count; ++i) {
    if (buf.readUInt32LE(at) !== 0x02014b50) throw new Error('bad central directory entry');
    const method = buf.readUInt16LE(at + 10), crc = buf.readUInt32LE(at + 16);
    const csize = buf.readUInt32LE(at + 20), usize = buf.readUInt32LE(at + 24);
    const nlen = buf.readUInt16LE(at + 28), xlen = buf.readUInt16LE(at + 30), clen = buf.readUInt16LE(at + 32);
    const local = buf.readUInt32LE(at + 42);
    const name = buf.toString('utf8', at + 46, at + 46 + nlen);
    if (buf.readUInt32LE(local) !== 0x04034b50) throw new Error(`bad local header of ${name}`);
    const start = local + 30 + buf.readUInt16LE(local + 26) + buf.readUInt16LE(local + 28);
    const raw = buf.subarray(start, start + csize);
    const data = method === 0 ? raw : method === 8 ? zlib.inflateRawSync(raw) : null;
    if (!data) throw new Error(`${name}: compression method ${method}`);
    if (data.length !== usize) throw new Error(`${name}: size ${data.length}, directory says ${usize}`);
    if (zlib.crc32 && zlib.crc32(data) !== crc) throw new Error(`${name}: crc mismatch`);
    files[name] = data;
    at += 46 + nlen + xlen + clen;
  }
  return files;
}

function main() {
  const [modulesArg, ...inputs] = process.argv.slice(2);
  if (!inputs.length) {
    console.error('usage: node lottie_schema_check.js NODE_MODULES FILE.json|FILE.lottie...');
    process.exit(2);
  }
  const nodeModules = path.resolve(modulesArg);
  const specs = path.join(nodeModules, '@lottie-animation-community', 'lottie-specs');
  const { Ajv2020 } = require(path.join(nodeModules, 'ajv', 'dist', '2020'));
  const { LottieValidator, get_schema_path } = require(path.join(specs, 'src', 'validator-node.js'));
  const schema = JSON.parse(fs.readFileSync(get_schema_path(), 'utf8'));
  const validator = new LottieValidator(Ajv2020, schema);
  let bad = 0;
  const check = (name, text) => {
    const errors = validator.validate(JSON.parse(text)).filter((e) => e.type === 'error');
    for (const e of errors) console.log(`${name}: ${e.path || '/'}: ${e.message}`);
    if (!errors.length) console.log(`${name}: valid`);
    bad += errors.length;
  };
  for (const f of inputs) {
    try {
      if (!f.endsWith('.lottie')) { check(f, fs.readFileSync(f, 'utf8')); continue; }
      const files = unzip(fs.readFileSync(f));
      if (!files['manifest.json']) throw new Error('no manifest.json');
      const manifest = JSON.parse(files['manifest.json'].toString('utf8'));
      if (!Array.isArray(manifest.animations) || !manifest.animations.length) throw new Error('manifest names no animation');
      for (const a of manifest.animations) {
        const entry = files[`animations/${a.id}.json`];
        if (!entry) throw new Error(`manifest names ${a.id}, no animations/${a.id}.json`);
        check(`${f}:animations/${a.id}.json`, entry.toString('utf8'));
      }
    } catch (e) {
      console.log(`${f}: ${String(e.message || e).split('\n')[0]}`);
      ++bad;
    }
  }
  process.exit(bad ? 1 : 0);
}

main();
