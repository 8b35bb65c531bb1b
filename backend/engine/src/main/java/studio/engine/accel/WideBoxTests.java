package studio.engine.accel;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;

/**
 * Chooses the {@link WideBoxTest} once, when this class is first used (Lucene's
 * {@code VectorizationProvider}): the Vector API implementation when the JVM is of feature version
 * 20 or newer (JDK 17's incubator API allocated on every ray in {@code WideWalkTest}, JDK 25's
 * nothing, and its walks are faster in {@code WideBvhBenchmark}, docs/speed.md), has the
 * {@code jdk.incubator.vector} module (run with {@code --add-modules jdk.incubator.vector}) and
 * has its optimising compiler (not C1 alone, {@code -XX:TieredStopAtLevel=1}, where every vector
 * operation is a call and an allocation); {@link ScalarBoxTest} everywhere else. The system
 * property {@code studio.vector} = {@code on} or {@code off} forces the choice (tests run both);
 * {@code on} without the module fails. The vector class is loaded only through this choice, by
 * name, so a JVM without the module never links it.
 */
public final class WideBoxTests {

    /** The system property that forces the choice: on, off (anything else: automatic). */
    public static final String PROPERTY = "studio.vector";
    private static final String VECTOR_MODULE = "jdk.incubator.vector";
    private static final String VECTOR_CLASS = "studio.engine.accel.VectorBoxTest";
    private static final WideBoxTest CHOSEN = choose(System.getProperty(PROPERTY, "auto"));

    private WideBoxTests() {
    }

    /** The box test of this JVM. */
    public static WideBoxTest get() {
        return CHOSEN;
    }

    /** Whether {@link #get} is the Vector API implementation. */
    public static boolean vectorized() {
        return !(CHOSEN instanceof ScalarBoxTest);
    }

    static WideBoxTest choose(String setting) {
        if (setting.equals("off")) {
            return new ScalarBoxTest();
        }
        boolean hasModule = ModuleLayer.boot().findModule(VECTOR_MODULE).isPresent();
        if (setting.equals("on")) {
            if (!hasModule) {
                throw new IllegalStateException(PROPERTY + "=on needs --add-modules " + VECTOR_MODULE);
            }
            return vector();
        }
        boolean c1Only = System.getProperty("java.vm.info", "").contains("emulated-client");
        if (hasModule && Runtime.version().feature() >= 20 && !c1Only) {
            try {
                return vector();
            } catch (LinkageError | IllegalStateException e) {
                return new ScalarBoxTest();
            }
        }
        return new ScalarBoxTest();
    }

    private static WideBoxTest vector() {
        try {
            MethodHandles.Lookup lookup = MethodHandles.lookup();
            Class<?> type = lookup.findClass(VECTOR_CLASS);
            return (WideBoxTest) lookup.findConstructor(type, MethodType.methodType(void.class)).invoke();
        } catch (ClassNotFoundException | NoSuchMethodException | IllegalAccessException e) {
            throw new IllegalStateException(VECTOR_CLASS + " is missing from the engine's jar", e);
        } catch (RuntimeException | Error e) {
            throw e;
        } catch (Throwable t) {
            throw new IllegalStateException(t);
        }
    }
}
