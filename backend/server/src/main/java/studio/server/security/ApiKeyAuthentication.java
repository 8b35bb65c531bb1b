package studio.server.security;

import java.util.List;

import org.springframework.security.authentication.AuthenticationProvider;
import org.springframework.security.authentication.UsernamePasswordAuthenticationToken;
import org.springframework.security.core.Authentication;
import org.springframework.security.oauth2.server.resource.InvalidBearerTokenException;
import org.springframework.security.oauth2.server.resource.authentication.BearerTokenAuthenticationToken;

/**
 * Signs in a bearer token that is one of the API keys, as the key's name. A token that is not a key
 * is left to the JWT provider when JWTs are on (null), else refused.
 */
final class ApiKeyAuthentication implements AuthenticationProvider {

    private final ApiKeys keys;
    private final boolean jwtsToo;

    ApiKeyAuthentication(ApiKeys keys, boolean jwtsToo) {
        this.keys = keys;
        this.jwtsToo = jwtsToo;
    }

    @Override
    public Authentication authenticate(Authentication authentication) {
        String token = ((BearerTokenAuthenticationToken) authentication).getToken();
        String name = keys.principal(token);
        if (name != null) {
            return UsernamePasswordAuthenticationToken.authenticated(name, null, List.of());
        }
        if (jwtsToo) {
            return null;
        }
        throw new InvalidBearerTokenException("unknown API key");
    }

    @Override
    public boolean supports(Class<?> authentication) {
        return BearerTokenAuthenticationToken.class.isAssignableFrom(authentication);
    }
}
