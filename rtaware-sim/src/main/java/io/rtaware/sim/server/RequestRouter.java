package io.rtaware.sim.server;

import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Routes each message a client sends to the device it addresses: REQ to
 * {@link DeviceHandler#request} (a RESP_NACK for a device the server lacks, where Player stays
 * silent), CMD to {@link DeviceHandler#command} (ignored for a device the server lacks, as
 * Player does). Any other message type is a protocol error. Thread-safe (immutable).
 */
final class RequestRouter implements ClientSession.Handler {

    private final Map<Integer, DeviceHandler> byInterf = new HashMap<>();
    private final MessageFactory messages;

    /**
     * @param handlers every device at index 0, {@code player:0} included
     * @param messages the encoder of NACKs
     */
    RequestRouter(List<DeviceHandler> handlers, MessageFactory messages) {
        for (DeviceHandler h : handlers) {
            byInterf.put(h.interf(), h);
        }
        this.messages = messages;
    }

    @Override
    public void handle(ClientSession client, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.type() != MessageType.REQ && h.type() != MessageType.CMD) {
            throw new PlayerProtocolException(0, "header.type", "a client may send only REQ (3) or CMD (2), got "
                    + h.type() + " (" + MessageType.name(h.type()) + ")");
        }
        DeviceHandler device = h.index() == 0 ? byInterf.get(h.interf()) : null;
        if (h.type() == MessageType.CMD) {
            if (device != null) {
                device.command(h, body);
            }
        } else if (device == null) {
            client.reply(messages.nack(h));
        } else {
            device.request(client, h, body);
        }
    }
}
