package io.rtaware.sim.server;

import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.DeviceRequest;
import io.rtaware.player.protocol.DriverInfo;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import java.util.List;

/**
 * {@code player:0}, the server itself: DEVLIST, DRIVERINFO, DEV (open and close, i.e.
 * subscriptions), DATA (a PULL round), DATAMODE and ADD_REPLACE_RULE (NACKed beyond the
 * per-client rule limit, as Player NACKs a request that failed). Not in the device list, as in
 * Player. Thread-safe.
 */
final class PlayerDevice implements DeviceHandler {

    private final List<DeviceHandler> devices;
    private final List<DeviceAddress> deviceList;
    private final MessageFactory messages;

    /**
     * @param devices the devices the server lists, in DEVLIST order
     * @param messages the encoder
     */
    PlayerDevice(List<DeviceHandler> devices, MessageFactory messages) {
        this.devices = List.copyOf(devices);
        this.deviceList = devices.stream().map(d -> messages.address(d.interf())).toList();
        this.messages = messages;
    }

    @Override
    public int interf() {
        return Interfaces.PLAYER;
    }

    @Override
    public String driverName() {
        return "player";
    }

    @Override
    public void request(ClientSession client, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        switch (h.subtype()) {
            case Subtypes.PLAYER_REQ_DEVLIST -> client.reply(messages.ack(h,
                    w -> PlayerCodec.writeDeviceList(w, deviceList)));
            case Subtypes.PLAYER_REQ_DRIVERINFO -> {
                DriverInfo info = PlayerCodec.readDriverInfo(body);
                DeviceHandler device = device(info.device());
                if (device == null) {
                    client.reply(messages.nack(h));
                } else {
                    client.reply(messages.ack(h, w -> PlayerCodec.writeDriverInfo(w,
                            new DriverInfo(messages.address(device.interf()), device.driverName()))));
                }
            }
            case Subtypes.PLAYER_REQ_DEV -> openOrClose(client, h, PlayerCodec.readDeviceRequest(body));
            case Subtypes.PLAYER_REQ_DATA -> client.pullRound(messages.ack(h, MessageFactory.Body.EMPTY));
            case Subtypes.PLAYER_REQ_DATAMODE -> {
                int mode = PlayerCodec.readDataMode(body);
                if (mode == Subtypes.DATAMODE_PUSH || mode == Subtypes.DATAMODE_PULL) {
                    client.setPull(mode == Subtypes.DATAMODE_PULL);
                    client.reply(messages.ack(h, MessageFactory.Body.EMPTY));
                } else {
                    client.reply(messages.nack(h));
                }
            }
            case Subtypes.PLAYER_REQ_ADD_REPLACE_RULE -> addRule(client, h, PlayerCodec.readReplaceRule(body));
            default -> client.reply(messages.nack(h));
        }
    }

    private void openOrClose(ClientSession client, PlayerHeader h, DeviceRequest req) {
        DeviceHandler device = device(req.device());
        DeviceAddress a = messages.address(req.device().interf(), req.device().index());
        if (device == null || (req.access() != Subtypes.ACCESS_OPEN && req.access() != Subtypes.ACCESS_CLOSE)) {
            client.reply(messages.reply(h, MessageType.RESP_NACK,
                    w -> PlayerCodec.writeDeviceRequest(w, new DeviceRequest(a, Subtypes.ACCESS_ERROR, ""))));
            return;
        }
        int key = DeviceHandler.key(a.interf(), a.index());
        if (req.access() == Subtypes.ACCESS_OPEN) {
            client.subscribe(key);
        } else {
            client.unsubscribe(key);
        }
        client.reply(messages.ack(h, w -> PlayerCodec.writeDeviceRequest(w,
                new DeviceRequest(a, req.access(), device.driverName()))));
    }

    private void addRule(ClientSession client, PlayerHeader h, ReplaceRule rule) {
        if (rule.replace() < Subtypes.REPLACE_ACCEPT || rule.replace() > Subtypes.REPLACE_IGNORE) {
            client.reply(messages.nack(h));
        } else if (!client.addRule(rule)) {
            client.reply(messages.nack(h));
        } else {
            client.reply(messages.ack(h, MessageFactory.Body.EMPTY));
        }
    }

    /** @return the handler of a listed device, or null if the server lacks it */
    private DeviceHandler device(DeviceAddress a) {
        if (a.index() != 0) {
            return null;
        }
        for (DeviceHandler d : devices) {
            if (d.interf() == a.interf()) {
                return d;
            }
        }
        return null;
    }
}
