package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.test.context.runner.ApplicationContextRunner;

import studio.server.scene.format.SceneLimits;
import studio.server.system.StudioProperties;

/** The scene limits the service configures from studio.limits.*. */
class SceneConfigurationTest {

    private final ApplicationContextRunner context = new ApplicationContextRunner()
            .withUserConfiguration(Properties.class);

    @EnableConfigurationProperties(StudioProperties.class)
    static class Properties {
    }

    @Test
    void limitsLeftUnsetAreTheFormatsDefaultLimits() {
        context.run(started -> assertThat(SceneConfiguration.limits(started.getBean(StudioProperties.class).limits()))
                .isEqualTo(SceneLimits.DEFAULTS));
    }

    @Test
    void limitsSetTakeTheirValues() {
        context.withPropertyValues("studio.limits.max-width=640", "studio.limits.max-pixel-samples=1000")
                .run(started -> {
                    SceneLimits limits = SceneConfiguration.limits(started.getBean(StudioProperties.class).limits());
                    assertThat(limits.maxWidth()).isEqualTo(640);
                    assertThat(limits.maxPixelSamples()).isEqualTo(1000);
                    assertThat(limits.maxHeight()).isEqualTo(SceneLimits.DEFAULTS.maxHeight());
                });
    }
}
