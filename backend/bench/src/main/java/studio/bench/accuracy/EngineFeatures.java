package studio.bench.accuracy;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.RecordComponent;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.sampler.Sampler;

/**
 * What the engine offers, found at run time, so the bench runs the samplers and the adaptive
 * sampling that exist in the engine it is built with, and skips the rest: samplers by asking
 * {@link Sampler#of}, adaptive sampling by looking for an {@code adaptiveThreshold} component of
 * {@link RenderSettings} and a {@code samplesTaken} component of {@link RenderResult}.
 */
final class EngineFeatures {

    /** The sampler names the bench tries, in the order it reports them. */
    static final List<String> SAMPLER_NAMES = List.of("regular", "random", "jittered", "multijittered", "sobol", "halton");

    static final String ADAPTIVE_THRESHOLD = "adaptiveThreshold";

    private EngineFeatures() {
    }

    /** The sampler {@code name} with n samples per pixel, or empty if the engine does not have it at n. */
    static Optional<Sampler> sampler(String name, int samplesPerPixel) {
        try {
            return Optional.of(Sampler.of(name, samplesPerPixel));
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    /** True if RenderSettings carries an adaptive threshold. */
    static boolean hasAdaptive() {
        return component(ADAPTIVE_THRESHOLD) != null;
    }

    /**
     * A copy of {@code base} with the named components replaced (e.g. "sampler", "seed",
     * "adaptiveThreshold"); every other component keeps its value, whatever components the record has.
     *
     * @throws IllegalArgumentException if a name is not a component, or the engine refuses the values
     */
    static RenderSettings with(RenderSettings base, Map<String, ?> replacements) {
        RecordComponent[] components = RenderSettings.class.getRecordComponents();
        Map<String, Object> values = new LinkedHashMap<>();
        Class<?>[] types = new Class<?>[components.length];
        for (int i = 0; i < components.length; i++) {
            types[i] = components[i].getType();
            values.put(components[i].getName(), read(components[i].getAccessor(), base));
        }
        for (Map.Entry<String, ?> e : replacements.entrySet()) {
            if (!values.containsKey(e.getKey())) {
                throw new IllegalArgumentException("RenderSettings has no component '" + e.getKey() + "'");
            }
            values.put(e.getKey(), e.getValue());
        }
        try {
            Constructor<RenderSettings> canonical = RenderSettings.class.getDeclaredConstructor(types);
            return canonical.newInstance(values.values().toArray());
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            throw new IllegalStateException(e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot build RenderSettings", e);
        }
    }

    /** Samples the render traced, from RenderResult.samplesTaken if the engine counts them, else pixels x samples. */
    static long samplesTaken(RenderResult result, RenderSettings settings) {
        try {
            Method counted = RenderResult.class.getMethod("samplesTaken");
            return ((Number) counted.invoke(result)).longValue();
        } catch (NoSuchMethodException e) {
            return (long) settings.width() * settings.height() * settings.sampler().samplesPerPixel();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read RenderResult.samplesTaken", e);
        }
    }

    private static RecordComponent component(String name) {
        for (RecordComponent c : RenderSettings.class.getRecordComponents()) {
            if (c.getName().equals(name)) {
                return c;
            }
        }
        return null;
    }

    private static Object read(Method accessor, Object record) {
        try {
            return accessor.invoke(record);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read " + accessor.getName(), e);
        }
    }
}
