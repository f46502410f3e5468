"""Writes an MCAP file with the official Python `mcap` writer, as another program would:
lz4 chunks and, with --no-summary, no summary section (both valid MCAP). Message i goes on
channel /a or /b (i odd), log time 1000 * i ns, payload b"foreign i".

usage: write_foreign_mcap.py OUT.mcap COUNT [--no-summary]
"""
import sys

from mcap.writer import CompressionType, IndexType, Writer


def main() -> int:
    out, count = sys.argv[1], int(sys.argv[2])
    no_summary = "--no-summary" in sys.argv[3:]
    with open(out, "wb") as f:
        options = dict(chunk_size=1024, compression=CompressionType.LZ4)
        if no_summary:
            options.update(index_types=IndexType.NONE, repeat_channels=False, repeat_schemas=False,
                           use_statistics=False, use_summary_offsets=False)
        w = Writer(f, **options)
        w.start(profile="", library="python mcap (rtaware test)")
        schema = w.register_schema(name="test/Foreign", encoding="jsonschema", data=b"{}")
        a = w.register_channel(topic="/a", message_encoding="json", schema_id=schema)
        b = w.register_channel(topic="/b", message_encoding="json", schema_id=schema)
        for i in range(count):
            w.add_message(channel_id=b if i % 2 else a, log_time=1000 * i, publish_time=1000 * i,
                          data=b"foreign %d" % i, sequence=i)
        w.finish()
    return 0


if __name__ == "__main__":
    sys.exit(main())
