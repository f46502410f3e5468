package io.rtaware.sim.server;

/**
 * A message ready to write to a client, with the address fields replace rules look at.
 *
 * @param bytes the encoded message (header and body)
 * @param interf the device's interface code
 * @param index the device's index
 * @param type the message type
 * @param subtype the message subtype
 */
record Outgoing(byte[] bytes, int interf, int index, int type, int subtype) {

    /** @return a message replace rules never apply to (a reply, SYNCH or the banner) */
    static Outgoing control(byte[] bytes) {
        return new Outgoing(bytes, 0, 0, 0, 0);
    }
}
