package io.rtaware.live;

/**
 * The live view cannot listen where its {@link LiveOptions} say: the port is in use, or the bind
 * address does not resolve to an address of this machine. The message is one line that names the
 * address and port, fit to show the user as it is.
 */
public final class LiveAddressException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /**
     * @param message one line naming the address, the port and the reason
     */
    public LiveAddressException(String message) {
        super(message);
    }
}
