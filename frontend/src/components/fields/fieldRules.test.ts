import { describe, expect, it } from 'vitest';
import { parseHexColor } from './ColorField';
import { check } from './NumberField';

describe('parseHexColor', () => {
  it('reads #rgb, rgb, rrggbb and #RRGGBB as #rrggbb; refuses names and bad digits', () => {
    expect(parseHexColor('#f00')).toBe('#ff0000');
    expect(parseHexColor('f80')).toBe('#ff8800');
    expect(parseHexColor('FF0000')).toBe('#ff0000');
    expect(parseHexColor(' #00Ff00 ')).toBe('#00ff00');
    expect(parseHexColor('red')).toBeNull();
    expect(parseHexColor('#ff00')).toBeNull();
    expect(parseHexColor('#gg0000')).toBeNull();
  });
});

describe('check (a typed number)', () => {
  it('says why a value is refused, in the server’s words for exclusive bounds', () => {
    expect(check('-1', { min: 0, minExclusive: true })).toBe('must be greater than 0');
    expect(check('0', { min: 0 })).toBeUndefined();
    expect(check('180', { max: 180, maxExclusive: true })).toBe('must be less than 180');
    expect(check('8000', { max: 4096 })).toBe('must be at most 4096');
    expect(check('2.5', { integer: true })).toBe('must be a whole number');
    expect(check('abc', {})).toBe('"abc" is not a number');
    expect(check('', {})).toBe('enter a number');
    expect(check('  ', {})).toBe('enter a number');
  });
});
