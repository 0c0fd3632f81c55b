// Reads MCAP files with the official TypeScript reader (@mcap/core, installed by the console's front-end `npm ci`,
// with fzstd to decompress zstd chunks)
// and prints one JSON object per file: whether the file is complete, the message count per topic, the schemas and
// messages that parse as JSON, and the CRCs checked (chunk CRCs by the streaming reader, the data section CRC here, the
// summary CRC by the indexed reader). A file cut short is read by the streaming reader up to its last complete chunk.
// Usage: node mcap-check.cjs <web dir with node_modules> <file.mcap>...
"use strict";
const fs = require("fs");
const path = require("path");
const { createRequire } = require("module");

const web = process.argv[2];
const mcap = createRequire(path.join(path.resolve(web), "package.json"))("@mcap/core");
const { crc32 } = createRequire(require.resolve("@mcap/core", { paths: [path.resolve(web)] }))("@foxglove/crc");
const fzstd = createRequire(path.join(path.resolve(web), "package.json"))("fzstd");
const decompressHandlers = { zstd: (data, size) => fzstd.decompress(data, new Uint8Array(Number(size))) };

function stream(bytes) {
  const reader = new mcap.McapStreamReader({ validateCrcs: true, decompressHandlers });
  reader.append(bytes);
  const channels = new Map();
  const schemas = new Map();
  const counts = {};
  let complete = false;
  let dataEndCrcOk = null;
  let offset = 0;
  let badJson = 0;
  const decoder = new TextDecoder();
  for (let record; (record = reader.nextRecord()); ) {
    switch (record.type) {
      case "Schema":
        schemas.set(record.id, record);
        JSON.parse(decoder.decode(record.data));
        break;
      case "Channel":
        channels.set(record.id, record);
        if (!(record.topic in counts)) counts[record.topic] = 0; // the summary repeats the channels
        break;
      case "Message": {
        const topic = channels.get(record.channelId).topic;
        counts[topic] += 1;
        try { JSON.parse(decoder.decode(record.data)); } catch { badJson += 1; }
        break;
      }
      case "DataEnd":
        dataEndCrcOk = record.dataSectionCrc === 0 || record.dataSectionCrc === crc32(bytes.subarray(0, dataEndOffset(bytes)));
        break;
      case "Footer":
        complete = true;
        break;
    }
  }
  return { complete, counts, schemas: schemas.size, channels: channels.size, badJson, dataEndCrcOk, done: reader.done() };
}

// The data end record's offset: the footer names the summary start; the data end (13 bytes) sits just before it.
function dataEndOffset(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const footer = bytes.length - 8 - (1 + 8 + 8 + 8 + 4);
  const summaryStart = Number(view.getBigUint64(footer + 9, true));
  return (summaryStart === 0 ? footer : summaryStart) - 13;
}

async function indexed(bytes) {
  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  };
  const reader = await mcap.McapIndexedReader.Initialize({ readable, decompressHandlers });
  const counts = {};
  for (const [, channel] of reader.channelsById) counts[channel.topic] = 0;
  for await (const message of reader.readMessages({ validateCrcs: true })) {
    counts[reader.channelsById.get(message.channelId).topic] += 1;
  }
  const statistics = {};
  for (const [id, count] of reader.statistics.channelMessageCounts) statistics[reader.channelsById.get(id).topic] = Number(count);
  const attachments = [];
  for await (const a of reader.readAttachments()) attachments.push(a.name);
  return { counts, statistics, chunks: reader.chunkIndexes.length, compressions: [...new Set(reader.chunkIndexes.map((c) => c.compression))], attachments, metadata: reader.metadataIndexes.map((m) => m.name) };
}

(async () => {
  for (const file of process.argv.slice(3)) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const result = { file, stream: null, indexed: null, error: null };
    try {
      result.stream = stream(bytes);
      if (result.stream.complete) result.indexed = await indexed(bytes);
    } catch (error) {
      result.error = String(error && error.message ? error.message : error);
    }
    process.stdout.write(JSON.stringify(result) + "\n");
  }
})();
