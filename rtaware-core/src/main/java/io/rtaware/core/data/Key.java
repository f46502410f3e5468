package io.rtaware.core.data;

import java.util.Objects;
import java.util.function.Supplier;
import java.util.regex.Pattern;

/**
 * The name and type of one state variable in the data store, with the factory that allocates
 * its buffers. Two keys are the same variable when their names are equal; a consumer whose key
 * has the same name as the producer's but another type is a type mismatch, reported before
 * anything runs. Immutable and thread-safe.
 *
 * @param <T> the value type
 */
public final class Key<T extends StateValue<T>> {

    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_][A-Za-z0-9_.:/-]*");

    private final String name;
    private final Class<T> type;
    private final Supplier<T> factory;

    private Key(String name, Class<T> type, Supplier<T> factory) {
        this.name = name;
        this.type = type;
        this.factory = factory;
    }

    /**
     * @param name the variable's name, e.g. {@code laser} or {@code motion.avoid}
     * @param type the value class
     * @param factory allocates one empty buffer; called only during initialization
     * @param <T> the value type
     * @return the key
     * @throws IllegalArgumentException if the name is empty or has characters other than
     *     letters, digits and {@code _ . : / -}
     */
    public static <T extends StateValue<T>> Key<T> of(String name, Class<T> type, Supplier<T> factory) {
        Objects.requireNonNull(name, "name");
        if (!NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("key name '" + name
                    + "' is not valid (letters, digits and _ . : / - only, not starting with punctuation)");
        }
        return new Key<>(name, Objects.requireNonNull(type, "type"), Objects.requireNonNull(factory, "factory"));
    }

    /** @return the variable's name */
    public String name() {
        return name;
    }

    /** @return the value class */
    public Class<T> type() {
        return type;
    }

    /**
     * Allocates a buffer for this key; for initialization only.
     *
     * @return a new buffer of the key's type
     * @throws IllegalStateException if the factory returns null or an instance of another class
     */
    public T newBuffer() {
        T value = factory.get();
        if (value == null || !type.isInstance(value)) {
            throw new IllegalStateException("factory of key '" + name + "' returned "
                    + (value == null ? "null" : value.getClass().getName()) + " instead of " + type.getName());
        }
        return value;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Key<?> other && other.name.equals(name) && other.type.equals(type);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + type.hashCode();
    }

    @Override
    public String toString() {
        return name + ":" + type.getSimpleName();
    }
}
