package io.rtaware.foxglove;

/**
 * The Foxglove server cannot listen where it was told: the port is in use, or the host does not
 * resolve to an address of this machine. The message is one line naming the address and the
 * reason, fit to show the user as it is.
 */
public final class FoxgloveAddressException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /**
     * @param message one line naming the address and the reason
     */
    public FoxgloveAddressException(String message) {
        super(message);
    }
}
