/**
 * Sun XDR (RFC 4506) encoding as Player uses it on the wire: big-endian 4-byte items, 8-byte
 * doubles and longs, byte strings padded to a multiple of 4, and variable arrays preceded by
 * their element count. {@link io.rtaware.player.xdr.XdrReader} decodes from a byte array it
 * does not copy and checks every read against the bytes present, so corrupt input gives a
 * {@link io.rtaware.player.xdr.PlayerProtocolException} naming the byte offset and field;
 * {@link io.rtaware.player.xdr.XdrWriter} encodes into a growable buffer that is reused from
 * message to message.
 */
package io.rtaware.player.xdr;
