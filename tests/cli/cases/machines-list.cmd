# The machine profiles that come with tape, and a user's own beside them (it hides none here).
export XDG_CONFIG_HOME=$PWD/config
$TAPE machines; echo "exit $?"
mkdir -p config/tape/machines
printf 'name = "shop-lathe"\ntitle = "The shop lathe"\nkind = "lathe"\nsource = "our notes"\n' > config/tape/machines/shop-lathe.toml
printf 'name = "broken"\nkind = "drill"\nsource = "x"\n' > config/tape/machines/broken.toml
# The user's folder is a temporary one: said here as config/.
$TAPE machines 2>&1 | sed "s|$PWD/||g"; echo "exit $?"
$TAPE machines show shop-lathe | sed "s|$PWD/||g"; echo "exit $?"
