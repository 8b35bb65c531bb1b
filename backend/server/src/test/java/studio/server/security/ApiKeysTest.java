package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** studio.security.api-keys read without a server. */
class ApiKeysTest {

    @Test
    void keyNamesItsPrincipal() {
        ApiKeys keys = ApiKeys.parse("alice:a-secret, bob : b-secret");
        assertThat(keys.size()).isEqualTo(2);
        assertThat(keys.principal("a-secret")).isEqualTo("alice");
        assertThat(keys.principal("b-secret")).isEqualTo("bob");
        assertThat(keys.principal("a-secre")).isNull();
        assertThat(keys.principal("")).isNull();
    }

    @Test
    void keyMayContainColons() {
        assertThat(ApiKeys.parse("ci:abc:def").principal("abc:def")).isEqualTo("ci");
    }

    @Test
    void blankMeansNoKeys() {
        assertThat(ApiKeys.parse("").size()).isZero();
        assertThat(ApiKeys.parse("  ").principal("")).isNull();
    }

    @Test
    void rejectsAnEntryWithoutNameOrKeyWithoutRepeatingIt() {
        assertThatThrownBy(() -> ApiKeys.parse("alice:a-secret,just-a-secret"))
                .hasMessageContaining("entry 2").hasMessageNotContaining("just-a-secret");
        assertThatThrownBy(() -> ApiKeys.parse(":a-secret")).hasMessageContaining("entry 1");
        assertThatThrownBy(() -> ApiKeys.parse("alice:")).hasMessageContaining("entry 1");
    }

    @Test
    void rejectsOneKeyForTwoNames() {
        assertThatThrownBy(() -> ApiKeys.parse("alice:same,bob:same"))
                .hasMessageContaining("entry 2").hasMessageNotContaining("same");
    }
}
