-- A module beside a security test (tests/security/mods): require finds it
-- as "mods.sec_mod", in the script's own folder.
return { answer = 42, name = ... }
