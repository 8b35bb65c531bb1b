package studio.server.security;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.KeyPairGenerator;
import java.security.PrivateKey;
import java.security.spec.PKCS8EncodedKeySpec;
import java.time.Instant;
import java.util.Base64;
import java.util.Date;

import com.nimbusds.jose.JOSEException;
import com.nimbusds.jose.JWSAlgorithm;
import com.nimbusds.jose.JWSHeader;
import com.nimbusds.jose.crypto.RSASSASigner;
import com.nimbusds.jwt.JWTClaimsSet;
import com.nimbusds.jwt.SignedJWT;

/**
 * JWTs for the tests, signed with the test key whose public half the test server trusts
 * (security/jwt-test-public.pem), or with a key of nobody's (a forgery).
 */
final class TestTokens {

    private TestTokens() {
    }

    /** A token for {@code subject}, signed with the trusted test key, expiring at {@code expires}. */
    static String signed(String subject, Instant expires) throws Exception {
        return sign(subject, expires, trustedKey());
    }

    /** A token for {@code subject} that looks right but is signed with a key the server does not know. */
    static String forged(String subject) throws Exception {
        KeyPairGenerator generator = KeyPairGenerator.getInstance("RSA");
        generator.initialize(2048);
        return sign(subject, Instant.now().plusSeconds(300), generator.generateKeyPair().getPrivate());
    }

    private static String sign(String subject, Instant expires, PrivateKey key) throws JOSEException {
        JWTClaimsSet claims = new JWTClaimsSet.Builder().subject(subject).issueTime(new Date())
                .expirationTime(Date.from(expires)).build();
        SignedJWT jwt = new SignedJWT(new JWSHeader(JWSAlgorithm.RS256), claims);
        jwt.sign(new RSASSASigner(key));
        return jwt.serialize();
    }

    private static PrivateKey trustedKey() throws IOException, GeneralSecurityException {
        try (InputStream in = TestTokens.class.getResourceAsStream("/security/jwt-test-private.pem")) {
            String pem = new String(in.readAllBytes(), StandardCharsets.US_ASCII)
                    .replaceAll("-----[A-Z ]+-----", "").replaceAll("\\s", "");
            return KeyFactory.getInstance("RSA").generatePrivate(new PKCS8EncodedKeySpec(Base64.getDecoder().decode(pem)));
        }
    }
}
