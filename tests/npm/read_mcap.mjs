// An MCAP file as @mcap/core (npm) reads it, printed as JSON for a test to
// compare with dem's own reading: the header, each channel with its schema,
// and each message's times and SHA-256. Reads the file twice: with the
// indexed reader (footer, summary and its CRC, chunk indexes, message
// indexes) and the streaming reader with every CRC checked (chunks, data
// section); exits 1 with the error when either refuses the file.
//   node read_mcap.mjs FILE.mcap
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { createHash } from "node:crypto";
import { readFileSync } from "node:fs";

const path = process.argv[2];
const bytes = readFileSync(path);
const readable = {
  size: async () => BigInt(bytes.byteLength),
  read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
};
const digest = (data) => createHash("sha256").update(data).digest("hex");

try {
  const indexed = await McapIndexedReader.Initialize({ readable });
  const channels = [];
  for (const [id, channel] of indexed.channelsById) {
    const schema = indexed.schemasById.get(channel.schemaId);
    channels.push({
      id, topic: channel.topic, messageEncoding: channel.messageEncoding,
      schemaName: schema?.name, schemaEncoding: schema?.encoding,
      schema: schema ? new TextDecoder().decode(schema.data) : null,
    });
  }
  const messages = [];
  for await (const m of indexed.readMessages({ validateCrcs: true })) {
    messages.push([m.channelId, m.sequence, m.logTime.toString(), m.publishTime.toString(), digest(m.data)]);
  }
  const stream = new McapStreamReader({ validateCrcs: true });
  stream.append(bytes);
  let streamed = 0;
  let dataEnd = null;
  for (let record; (record = stream.nextRecord());) {
    if (record.type === "Message") streamed++;
    if (record.type === "DataEnd") dataEnd = record.dataSectionCrc;
  }
  console.log(JSON.stringify({
    profile: indexed.header.profile, library: indexed.header.library,
    chunks: indexed.chunkIndexes.length,
    statisticsMessageCount: indexed.statistics ? Number(indexed.statistics.messageCount) : null,
    channels, messages, streamedMessages: streamed, streamDone: stream.done(), dataSectionCrc: dataEnd,
  }));
} catch (error) {
  console.error(`@mcap/core refused ${path}: ${error.message}`);
  process.exit(1);
}
