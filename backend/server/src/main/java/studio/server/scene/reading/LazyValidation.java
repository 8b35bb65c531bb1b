package studio.server.scene.reading;

import java.util.function.Supplier;

import jakarta.validation.Validation;
import jakarta.validation.Validator;
import jakarta.validation.ValidatorFactory;

/**
 * Hibernate Validator, booted on first use (about 0.2 s in a cold JVM). The command line and the
 * benchmark read scenes with it: a plainly valid scene takes {@link SceneReader}'s fast path and
 * never boots it. Thread-safe; {@link #close} closes the factory if it was built.
 */
public final class LazyValidation implements Supplier<Validator>, AutoCloseable {

    private ValidatorFactory factory;
    private Validator validator;

    @Override
    public synchronized Validator get() {
        if (validator == null) {
            factory = Validation.buildDefaultValidatorFactory();
            validator = factory.getValidator();
        }
        return validator;
    }

    @Override
    public synchronized void close() {
        if (factory != null) {
            factory.close();
        }
    }
}
