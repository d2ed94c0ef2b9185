// Reads NMEA 0183 lines on stdin and prints, per line, one JSON object: {"line": ..., "delta": ...}
// (the Signal K delta of @signalk/nmea0183-signalk, null when it gives none) or {"line", "error"}.
// The independent reader of Reckoner's NMEA output in tests/connections/tst_nmea_signalk.cpp.
'use strict'
const Parser = require('@signalk/nmea0183-signalk')
const readline = require('readline')

const parser = new Parser()
const rl = readline.createInterface({ input: process.stdin, terminal: false })
rl.on('line', (line) => {
  if (line.trim() === '') return
  try {
    const delta = parser.parse(line.trim())
    process.stdout.write(JSON.stringify({ line: line.trim(), delta: delta || null }) + '\n')
  } catch (e) {
    process.stdout.write(JSON.stringify({ line: line.trim(), error: String(e.message) }) + '\n')
  }
})
