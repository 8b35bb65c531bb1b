package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.springframework.beans.factory.support.StaticListableBeanFactory;
import org.springframework.boot.test.system.CapturedOutput;
import org.springframework.boot.test.system.OutputCaptureExtension;
import org.springframework.security.oauth2.jwt.JwtDecoder;

/** The one start-up line that says whether sign-in is on, and how to turn it on; never a key. */
@ExtendWith(OutputCaptureExtension.class)
class SignInLogTest {

    private static SignIn signIn(String keys, boolean jwts) {
        StaticListableBeanFactory beans = new StaticListableBeanFactory();
        if (jwts) {
            beans.addBean("jwtDecoder", (JwtDecoder) token -> {
                throw new UnsupportedOperationException();
            });
        }
        SignInProperties properties = new SignInProperties(keys, 0, 0, Duration.ofSeconds(30), 8, 1024);
        return new SecurityConfiguration().signIn(properties, ApiKeys.parse(keys), beans.getBeanProvider(JwtDecoder.class));
    }

    @Test
    void signInOffSaysAnyoneCanUseThePortAndHowToTurnItOn(CapturedOutput output) {
        assertThat(signIn("", false).required()).isFalse();
        assertThat(output.getOut()).contains("Sign-in is off: anyone who reaches this port")
                .contains("studio.security.api-keys=NAME:KEY");
    }

    @Test
    void signInOnCountsTheKeysAndSaysWhetherJwtsAreOnWithoutAKey(CapturedOutput output) {
        assertThat(signIn("alice:secret-one,bob:secret-two", false).required()).isTrue();
        assertThat(signIn("", true).required()).isTrue();
        assertThat(output.getOut()).contains("Sign-in is on: 2 API keys, JWTs off")
                .contains("Sign-in is on: 0 API keys, JWTs accepted").doesNotContain("secret-");
    }

    @Test
    void limitsApplyOnlyWithSignInOn() {
        assertThat(signIn("", false).maxJobsPerPrincipal(9)).isEqualTo(Integer.MAX_VALUE);
        SignIn on = signIn("alice:k", false);
        assertThat(on.maxJobsPerPrincipal(9)).isEqualTo(4);
        assertThat(on.maxLiveViewsPerPrincipal(16)).isEqualTo(8);
        assertThat(on.maxLiveViewsPerPrincipal(1)).isEqualTo(1);
    }
}
