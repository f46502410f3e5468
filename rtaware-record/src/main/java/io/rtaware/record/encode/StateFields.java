package io.rtaware.record.encode;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;

/**
 * The fields of a data-store value class that a recording carries: its public instance fields of
 * primitive or primitive-array type, in declaration order, and, for classes with an {@code int
 * count()} method, that count (arrays are then cut to it). Found once per class by reflection;
 * reading them allocates nothing. Setting them back (for replay) also sets a private {@code count}
 * field, the convention of rtaware's fixed-capacity values.
 */
public final class StateFields {

    private final Class<?> type;
    private final List<Field> fields;
    private final MethodHandle countMethod;
    private final Field countField;

    private StateFields(Class<?> type, List<Field> fields, MethodHandle countMethod, Field countField) {
        this.type = type;
        this.fields = fields;
        this.countMethod = countMethod;
        this.countField = countField;
    }

    /**
     * @param type a value class
     * @return its recordable fields
     */
    public static StateFields of(Class<?> type) {
        List<Field> fields = new ArrayList<>();
        for (Field f : type.getDeclaredFields()) {
            int m = f.getModifiers();
            if (!Modifier.isPublic(m) || Modifier.isStatic(m)) {
                continue;
            }
            Class<?> t = f.getType();
            if (t.isPrimitive() || (t.isArray() && t.getComponentType().isPrimitive())) {
                fields.add(f);
            }
        }
        MethodHandle count = null;
        Field countField = null;
        try {
            Method m = type.getMethod("count");
            if (m.getReturnType() == int.class) {
                count = MethodHandles.publicLookup().unreflect(m).asType(MethodType.methodType(int.class, Object.class));
                Field cf = type.getDeclaredField("count");
                if (cf.getType() == int.class && !Modifier.isStatic(cf.getModifiers())) {
                    cf.setAccessible(true);
                    countField = cf;
                }
            }
        } catch (NoSuchMethodException | NoSuchFieldException | SecurityException | IllegalAccessException e) {
            // no count: arrays are carried whole
        }
        return new StateFields(type, List.copyOf(fields), count, countField);
    }

    /** @return the class */
    public Class<?> type() {
        return type;
    }

    /** @return the recordable fields in declaration order */
    public List<Field> fields() {
        return fields;
    }

    /** @return true if arrays are cut to a {@code count()} */
    public boolean counted() {
        return countMethod != null;
    }

    /**
     * @param value an instance
     * @return its {@code count()}, or -1 if the class has none
     */
    public int count(Object value) {
        if (countMethod == null) {
            return -1;
        }
        try {
            return (int) countMethod.invokeExact(value);
        } catch (Throwable e) {
            throw new IllegalStateException("count() of " + type.getName() + " failed", e);
        }
    }

    /**
     * @param value an instance
     * @return roughly how many bytes its recorded fields take (8 per scalar, arrays by length)
     */
    public long estimateBytes(Object value) {
        long bytes = 16;
        try {
            for (Field f : fields) {
                if (f.getType().isArray()) {
                    Object array = f.get(value);
                    bytes += array == null ? 0 : (long) java.lang.reflect.Array.getLength(array) * elementBytes(f.getType());
                } else {
                    bytes += 8;
                }
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + type.getName() + " not readable", e);
        }
        return bytes;
    }

    private static int elementBytes(Class<?> arrayType) {
        Class<?> c = arrayType.getComponentType();
        if (c == double.class || c == long.class) {
            return 8;
        }
        if (c == float.class || c == int.class) {
            return 4;
        }
        return c == short.class || c == char.class ? 2 : 1;
    }

    /**
     * Sets the private {@code count} field (replay).
     *
     * @param value an instance
     * @param count the count
     * @return false if the class has no such field
     */
    public boolean setCount(Object value, int count) {
        if (countField == null) {
            return false;
        }
        try {
            countField.setInt(value, count);
            return true;
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("count of " + type.getName() + " not settable", e);
        }
    }
}
