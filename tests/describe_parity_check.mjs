/*
 * Run the view's description (js/explorer/src/describe.js) on a corpus and print what it says,
 * for tests/test_describe.py, which compares it with Python's (trinormal.explorer.describe):
 *   node tests/describe_parity_check.mjs CORPUS.json
 * CORPUS.json: { states: [{ state, winding, viewer }], normals: [[x, y, z]] }. Prints
 * { constants, states: [text], normals: [text] } as JSON.
 */
import { readFileSync } from "node:fs";
import { A_LITTLE, EDGE_ON, MENTION, describeState, directionWords } from "../js/explorer/src/describe.js";

const corpus = JSON.parse(readFileSync(process.argv[2], "utf8"));
process.stdout.write(
  JSON.stringify({
    constants: { MENTION, A_LITTLE, EDGE_ON },
    states: corpus.states.map(({ state, winding, viewer }) => describeState(state, winding, viewer)),
    normals: corpus.normals.map((n) => directionWords(n)),
  }),
);
