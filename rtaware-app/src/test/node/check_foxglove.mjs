// Reads an rtaware recording with Foxglove's own TypeScript libraries, as Foxglove does:
// @mcap/core (McapIndexedReader and McapStreamReader, CRCs validated), @mcap/support (zstd, lz4),
// @foxglove/rosmsg (the ros2msg schemas) and @foxglove/rosmsg2-serialization (CDR).
//
// usage: RTAWARE_NPM_PEERS=DIR node check_foxglove.mjs FILE.mcap
// DIR holds the node_modules of .ci/npm-peers.json (.ci/run installs them). Prints one line per
// check; exits 1 on the first failure.
import { readFileSync } from "node:fs";
import { open } from "node:fs/promises";
import { createRequire } from "node:module";

const file = process.argv[2];
const require = createRequire(process.env.RTAWARE_NPM_PEERS + "/package.json");
const { McapIndexedReader, McapStreamReader } = require("@mcap/core");
const { loadDecompressHandlers } = require("@mcap/support");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");

function fail(message) {
  console.log("FAIL: " + message);
  process.exit(1);
}

function readerFor(schema, channel) {
  if (channel.messageEncoding !== "cdr" || schema.encoding !== "ros2msg") {
    fail(`${channel.topic}: ${channel.messageEncoding} with a ${schema.encoding} schema`);
  }
  return new MessageReader(parse(new TextDecoder().decode(schema.data), { ros2: true }));
}

const decompressHandlers = await loadDecompressHandlers();
const handle = await open(file, "r");
const size = (await handle.stat()).size;
const readable = {
  size: async () => BigInt(size),
  read: async (offset, length) => {
    const buffer = new Uint8Array(Number(length));
    await handle.read(buffer, 0, buffer.length, Number(offset));
    return buffer;
  },
};
const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
if (indexed.header.profile !== "ros2") fail(`profile '${indexed.header.profile}'`);
const byChannel = new Map();
for (const [id, channel] of indexed.channelsById) {
  byChannel.set(id, readerFor(indexed.schemasById.get(channel.schemaId), channel));
}
let indexedCount = 0;
for await (const message of indexed.readMessages()) {
  byChannel.get(message.channelId).readMessage(message.data);
  indexedCount++;
}
await handle.close();
const expected = Number(indexed.statistics.messageCount);
if (indexedCount !== expected) fail(`indexed reader read ${indexedCount} of ${expected} messages`);
console.log(`ok: McapIndexedReader decoded all ${indexedCount} messages on ${byChannel.size} channels`);

const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(readFileSync(file));
const schemas = new Map();
const streamed = new Map();
let streamedCount = 0;
let last = -1n;
for (let record; (record = stream.nextRecord()); ) {
  if (record.type === "Schema") {
    schemas.set(record.id, record);
  } else if (record.type === "Channel") {
    streamed.set(record.id, readerFor(schemas.get(record.schemaId), record));
  } else if (record.type === "Message") {
    if (record.logTime < last) fail(`log time goes back: ${record.logTime} after ${last}`);
    last = record.logTime;
    streamed.get(record.channelId).readMessage(record.data);
    streamedCount++;
  }
}
if (!stream.done()) fail("the stream reader did not reach the end of the file");
if (streamedCount !== expected) fail(`stream reader read ${streamedCount} of ${expected} messages`);
console.log(`ok: McapStreamReader decoded all ${streamedCount} messages in file order, log times never going back`);
