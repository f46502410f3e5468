package io.rtaware.sim.server;

import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import java.util.ArrayDeque;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * What one client is owed: its subscriptions, its data mode, its replace rules and its queues.
 * Data is filtered by subscription, held until {@code REQ DATA} in PULL mode, replaced per the
 * rules, and bounded: beyond the queue limit the oldest queued data message is dropped (counted
 * in the next SYNCH OVERFLOW), so the stepping thread never waits for a slow client. Replies
 * are never dropped; {@link #reply} tells the caller when too many are unread. Thread-safe
 * (queues guarded by this object's monitor; subscriptions a concurrent set).
 */
final class ClientQueue {

    /** Replies beyond the data limit a client may leave unread before it is dropped. */
    static final int REPLY_SLACK = 1024;

    private final int queueLimit;
    private final byte[] synchOk;
    private final ReplaceRules rules;
    private final Set<Integer> subscriptions = ConcurrentHashMap.newKeySet();
    private final ArrayDeque<Outgoing> outbox = new ArrayDeque<>();
    private final ArrayDeque<Outgoing> held = new ArrayDeque<>();
    private boolean pull;
    private boolean roundOwed;
    private long dropped;
    private boolean closed;

    /**
     * @param queueLimit most data messages queued (and, separately, held)
     * @param maxRules most distinct replace rules
     * @param first what the client gets first (the banner)
     * @param synchOk the SYNCH that ends a PULL round
     */
    ClientQueue(int queueLimit, int maxRules, byte[] first, byte[] synchOk) {
        this.queueLimit = queueLimit;
        this.rules = new ReplaceRules(maxRules);
        this.synchOk = synchOk;
        outbox.add(Outgoing.control(first));
    }

    boolean subscribed(int deviceKey) {
        return subscriptions.contains(deviceKey);
    }

    void subscribe(int deviceKey) {
        subscriptions.add(deviceKey);
    }

    void unsubscribe(int deviceKey) {
        subscriptions.remove(deviceKey);
    }

    synchronized void setPull(boolean pullMode) {
        if (this.pull && !pullMode) {
            while (!held.isEmpty()) {
                outbox.add(held.poll());
            }
            roundOwed = false;
            notifyAll();
        }
        this.pull = pullMode;
    }

    /** @return false if the rule limit is reached (the rule is not added) */
    synchronized boolean addRule(ReplaceRule rule) {
        return rules.add(rule);
    }

    /**
     * Queues a reply.
     *
     * @return true if more replies are unread than the limit allows (drop the client)
     */
    synchronized boolean reply(byte[] message) {
        if (closed) {
            return false;
        }
        outbox.add(Outgoing.control(message));
        notifyAll();
        return outbox.size() > queueLimit + REPLY_SLACK;
    }

    /**
     * The ACK of REQ DATA, then (in PULL mode) the held round and a SYNCH, or the SYNCH after
     * the next data if nothing is held. In PUSH mode only the ACK.
     */
    synchronized void pullRound(byte[] ack) {
        if (closed) {
            return;
        }
        outbox.add(Outgoing.control(ack));
        if (pull) {
            if (held.isEmpty()) {
                roundOwed = true;
            } else {
                releaseRound();
            }
        }
        notifyAll();
    }

    /** Called by the stepping thread with the messages one world step published. */
    synchronized void deliver(List<Outgoing> batch) {
        if (closed) {
            return;
        }
        boolean any = false;
        for (Outgoing m : batch) {
            if (!subscriptions.contains(DeviceHandler.key(m.interf(), m.index()))) {
                continue;
            }
            any = true;
            enqueueData(pull ? held : outbox, m);
        }
        if (any && pull && roundOwed) {
            releaseRound();
        }
        if (any) {
            notifyAll();
        }
    }

    /**
     * Waits until something is queued and moves it to {@code into}.
     *
     * @return false once the queue is closed
     * @throws InterruptedException if interrupted while waiting
     */
    synchronized boolean take(List<Outgoing> into) throws InterruptedException {
        while (outbox.isEmpty() && !closed) {
            wait();
        }
        if (closed) {
            return false;
        }
        into.addAll(outbox);
        outbox.clear();
        return true;
    }

    synchronized boolean isClosed() {
        return closed;
    }

    /** @return true if this call closed the queue, false if it was closed already */
    boolean close() {
        synchronized (this) {
            if (closed) {
                return false;
            }
            closed = true;
            outbox.clear();
            held.clear();
            notifyAll();
        }
        subscriptions.clear();
        return true;
    }

    private void releaseRound() {
        while (!held.isEmpty()) {
            outbox.add(held.poll());
        }
        if (dropped > 0) {
            outbox.add(Outgoing.control(MessageFactory.synchOverflow(dropped)));
            dropped = 0;
        } else {
            outbox.add(Outgoing.control(synchOk));
        }
        roundOwed = false;
    }

    private void enqueueData(ArrayDeque<Outgoing> queue, Outgoing m) {
        int replace = rules.decide(m);
        if (replace == Subtypes.REPLACE_IGNORE) {
            return;
        }
        int data = 0;
        for (Iterator<Outgoing> it = queue.iterator(); it.hasNext(); ) {
            Outgoing q = it.next();
            if (q.type() != MessageType.DATA) {
                continue;
            }
            if (replace == Subtypes.REPLACE_REPLACE && q.interf() == m.interf() && q.index() == m.index()
                    && q.subtype() == m.subtype()) {
                it.remove();
            } else {
                data++;
            }
        }
        if (data >= queueLimit) {
            for (Iterator<Outgoing> it = queue.iterator(); it.hasNext(); ) {
                if (it.next().type() == MessageType.DATA) {
                    it.remove();
                    dropped++;
                    break;
                }
            }
        }
        queue.add(m);
    }
}
