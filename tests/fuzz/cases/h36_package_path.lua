-- nasty: package.path pointing at /etc (issue 13 item 2)
package.path = '/etc/?'
require 'passwd'
